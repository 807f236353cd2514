MODULE access_expression_to_var
! @format 2
! @section 5.2
! @expect semantic-error 8:14
! @description Table of section 5.2, row any other expression, column var: illegal; refused at the argument.
  VAR num n;
  PROC main()
    take_var n + 1;
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
