MODULE settings
! @format 2
! @section 2.20
! @section 5.3
! @expect ok
! @description LOCAL objects of different modules may share a name, and a LOCAL one may share its name with a global one elsewhere.
  LOCAL VAR num counter;
  LOCAL PROC init()
    counter := 0;
  ENDPROC
ENDMODULE
