MODULE access_expression_to_inout
! @format 2
! @section 5.2
! @expect semantic-error 8:16
! @description Table of section 5.2, row any other expression (a function call), column inout: illegal; refused at the argument.
  VAR num n;
  PROC main()
    take_inout twice(n);
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
