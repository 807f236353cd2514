MODULE refused_nested_operand
! @format 2
! @section 3.12
! @expect semantic-error 9:18
! @description A wrong operand inside a larger expression is refused at the start of the inner operation.
  VAR num n;
  VAR string s;
  PROC main()
    n := n * 2 + s * 3;
  ENDPROC
ENDMODULE
