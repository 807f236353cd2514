MODULE no_user_level (NOSTEPIN)
! @format 3
! @section 7.3
! @expect ok
! @description The entry routine is itself a routine of a NOSTEPIN module: RaiseToUser finds no user level above it, and the system error handler stops the task, with the error where it occurred (doc/rulings.md R-7.3-n).
! @output start
! @output handler
! @exit 1
! @error 4 15:5
  PROC main()
    tool;
  ENDPROC
  PROC tool()
    TPWrite "start";
    RAISE 4;
  ERROR
    TPWrite "handler";
    RaiseToUser \BreakOff;
  ENDPROC
ENDMODULE
