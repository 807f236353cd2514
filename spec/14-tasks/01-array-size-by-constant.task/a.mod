MODULE by_constant_a
! @format 4
! @task T_ROB1
! @section 14
! @expect ok
! @description Array sizes are compared by value: a dimension written as a constant in one task and as a literal in another is the same type, one shared persistent (R-14-c).
! @output B reads 2
  CONST num n := 2;
  PERS num arr{n} := [1, 2];
  PROC main()
  ENDPROC
ENDMODULE
