MODULE data_declaration_manual_examples
! @section 2.18
! @expect ok
! @description The example table of section 2.18.
  LOCAL VAR num counter;
  CONST num maxtemp := 39.5;
  PERS pos refpnt := [100.23, 778.55, 1183.98];
  TASK PERS num lasttemp := 19.2;
  <DDN>
ENDMODULE
