MODULE user_error_stops_task
! @format 3
! @section 7.1
! @section 4.11
! @expect ok
! @description A user error that no handler takes stops the task; the system error handler reports its number and the RAISE statement.
! @exit 1
! @error 17 10:5
  PROC p()
    RAISE 17;
  ENDPROC
  PROC main()
    p;
  ENDPROC
ENDMODULE
