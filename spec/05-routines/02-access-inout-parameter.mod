MODULE access_inout_parameter
! @format 2
! @section 5.2
! @expect ok
! @description Table of section 5.2, rows parameter inout: legal for in, inout and ref; the var and pers cells are execution errors (decided by the binding at run time), so accepted statically.
  VAR bool b;
  PROC pass(INOUT num x)
    take_in x;
    take_inout x;
    b := Present(x);
    IF IsVar(x) take_var x;
    IF IsPers(x) take_pers x;
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
