MODULE sign_is_not_part_of_literal
! @section 2.5
! @section 3.1
! @expect ok
! @description A sign is the unary operator of a <simple expr>, not part of the literal; white space may follow it.
  VAR num x;
  PROC main()
    x := -1;
    x := +2.5E-3;
    x := - 7;
  ENDPROC
ENDMODULE
