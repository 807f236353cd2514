MODULE present_of_required_parameter
! @format 2
! @section 5.2
! @section 11
! @expect ok
! @description Present may be applied to any parameter; for a required one it returns TRUE.
  VAR bool b;
  PROC show(num x)
    b := Present(x);
  ENDPROC
ENDMODULE
