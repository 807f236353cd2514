MODULE return_in_entry_routine
! @format 3
! @section 4.10
! @section 9.1
! @expect ok
! @description RETURN in the task's entry routine ends the evaluation of the task (section 4.10): exit 0, nothing after it runs.
! @output before
! @exit 0
  PROC main()
    TPWrite "before";
    RETURN;
    TPWrite "wrong";
  ENDPROC
ENDMODULE
