MODULE access_constant_to_inout
! @format 2
! @section 5.2
! @expect semantic-error 8:16
! @description Table of section 5.2, row constant, column inout: illegal; refused at the argument.
  CONST num limit := 10;
  PROC main()
    take_inout limit;
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
