MODULE cell
! @format 2
! @section 9.2
! @expect ok
! @description Ruling: a LOCAL object may have the name of another module of the task.
  LOCAL VAR num conveyor;
  PROC main()
    conveyor := speed;
  ENDPROC
ENDMODULE
