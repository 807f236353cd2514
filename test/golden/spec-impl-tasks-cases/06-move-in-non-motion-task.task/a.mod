MODULE move_a
! @format 4
! @task T_ROB1
! @section 14
! @expect ok
! @exit 1
! @error ERR_NOT_MOVETASK b.mod:5:5
! @description Only the motion task moves the robot: a move instruction in another task raises ERR_NOT_MOVETASK (R-14-e); unhandled, the system error handler stops that task, and the run ends with exit status 1.
! @output A ends
  PROC main()
    TPWrite "A ends";
  ENDPROC
ENDMODULE
