MODULE access_errno_to_var
! @format 2
! @section 5.2
! @expect semantic-error 7:14
! @description Table of section 5.2, row read-only variable (ERRNO), column var: illegal; refused at the argument.
  PROC main()
    take_var ERRNO;
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
