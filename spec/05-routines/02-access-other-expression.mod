MODULE access_other_expression
! @format 2
! @section 5.2
! @expect ok
! @description Table of section 5.2, row any other expression: legal for in parameters.
  VAR num n;
  PROC main()
    take_in 3;
    take_in n + 1;
    take_in twice(n);
  ENDPROC
  FUNC num twice(num x)
    RETURN 2 * x;
  ENDFUNC

  PROC take_in(num x)
  ENDPROC
  PROC take_var(VAR num x)
  ENDPROC
  PROC take_pers(PERS num x)
  ENDPROC
  PROC take_inout(INOUT num x)
  ENDPROC
ENDMODULE
