MODULE access_expression_to_pers
! @format 2
! @section 5.2
! @expect semantic-error 7:15
! @description Table of section 5.2, row any other expression, column pers: illegal; refused at the argument.
  PROC main()
    take_pers 5;
  ENDPROC

  PROC take_in(num x)
  ENDPROC
  PROC take_var(VAR num x)
  ENDPROC
  PROC take_pers(PERS num x)
  ENDPROC
  PROC take_inout(INOUT num x)
  ENDPROC
ENDMODULE
