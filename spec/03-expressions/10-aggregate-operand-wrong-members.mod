MODULE aggregate_operand_wrong_members
! @format 2
! @section 3.10
! @section 3.12
! @expect semantic-error 9:22
! @description Ruling R-3.10-operand1: p.rot * [...] makes the aggregate an orient, whose four components it must match in number (section 3.10); three members are refused at the aggregate.
  VAR pose p;
  PROC main()
    p.rot := p.rot * [0, 0, 1];
  ENDPROC
ENDMODULE
