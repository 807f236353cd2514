MODULE procedure_in_expression
! @format 2
! @section 3.11
! @expect semantic-error 8:10
! @description A procedure returns no value and cannot be called in an expression; refused at its name.
  VAR num x;
  PROC main()
    x := show(1);
  ENDPROC
  PROC show(num n)
  ENDPROC
ENDMODULE
