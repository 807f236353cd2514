MODULE access_var_parameter
! @format 2
! @section 5.2
! @expect ok
! @description Table of section 5.2, row parameter var: legal for in, var, inout and ref parameters.
  VAR bool b;
  PROC pass(VAR num x)
    take_in x;
    take_var x;
    take_inout x;
    b := Present(x);
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
