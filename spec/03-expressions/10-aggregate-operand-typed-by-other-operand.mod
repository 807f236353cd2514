MODULE aggregate_typed_by_other_operand
! @format 2
! @section 3.10
! @section 3.12
! @expect ok
! @description Ruling R-3.10-operand1: the other operand of an operator is a context that determines an aggregate's type, through the operator table: orient * [..] is an orient, pos + [..] and pos - [..] pos, pos * [..] the cross product, num * [..] and [..] / num a pos.
  VAR pose p;
  VAR orient o;
  VAR pos q;
  PROC main()
    o := p.rot * [0, 0, 0, 1];
    o := [1, 0, 0, 0] * o;
    q := p.trans + [1, 2, 3];
    q := [1, 2, 3] - q;
    q := q * [0, 0, 1];
    q := 2 * [1, 2, 3];
    q := [3, 6, 9] / 3;
    q := q - [1, 1, 1] + [0.5, 0.5, 0.5];
    IF q = p.trans + [0, 0, 0] q := [0, 0, 0];
  ENDPROC
ENDMODULE
