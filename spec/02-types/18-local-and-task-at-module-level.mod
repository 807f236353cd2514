MODULE local_and_task_at_module_level
! @format 2
! @section 2.18
! @expect ok
! @description LOCAL and TASK stand at module level before VAR, PERS and (LOCAL only) CONST.
  LOCAL VAR num a;
  LOCAL PERS num b := 0;
  LOCAL CONST num c := 1;
  TASK VAR num d;
  TASK PERS num e := 2;
ENDMODULE
