MODULE feeder
! @format 2
! @section 9.2
! @expect ok
! @description Ruling: the rule names global module objects only, so a LOCAL object may have its module's name.
  LOCAL VAR num feeder;
  LOCAL PROC init()
    feeder := 0;
  ENDPROC
ENDMODULE
