MODULE return_from_entry_handler
! @format 3
! @section 7.1
! @section 4.10
! @expect ok
! @description RETURN in the error handler of the entry routine ends the task normally: exit 0.
! @output handler
! @exit 0
  PROC main()
    RAISE 5;
  ERROR
    TPWrite "handler";
    RETURN;
  ENDPROC
ENDMODULE
