MODULE example_system_global_persistent
! @section 14
! @expect ok
! @description The declarations of chapter 14 (task 1 and task 2 in one module, tool1 of task 2 renamed tool2; the elided tooldata completed).
  PERS tooldata tool1 := [TRUE, [[0, 0, 100], [1, 0, 0, 0]], [1, [0, 0, 1], [1, 0, 0, 0], 0, 0, 0]];
  PERS tooldata tool2;
  PERS num state;
ENDMODULE
