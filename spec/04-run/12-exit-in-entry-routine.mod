MODULE exit_in_entry_routine
! @format 3
! @section 4.12
! @expect ok
! @description EXIT ends the execution of the task at once (section 4.12): exit 0.
! @output before
! @exit 0
  PROC main()
    TPWrite "before";
    EXIT;
    TPWrite "wrong";
  ENDPROC
ENDMODULE
