MODULE switch_passed_on
! @format 2
! @section 5.2
! @section 4.6
! @expect ok
! @description A switch parameter is tested with Present and passed on to a procedure with the conditional syntax.
  PROC valve(\switch fast)
  ENDPROC
  PROC close_valve(\switch fast)
    IF Present(fast) THEN
      valve \fast;
    ENDIF
    valve \fast ? fast;
  ENDPROC
ENDMODULE
