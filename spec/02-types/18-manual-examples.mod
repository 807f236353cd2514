MODULE manual_examples
! @format 2
! @section 2.18
! @expect ok
! @description The declaration examples of section 2.18, all at module level.
  LOCAL VAR num counter;
  CONST num maxtemp := 39.5;
  PERS pos refpnt := [100.23, 778.55, 1183.98];
  TASK PERS num lasttemp := 19.2;
  <DDN>
ENDMODULE
