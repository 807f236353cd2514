MODULE long_jump_skips_handlers
! @format 3
! @section 7.2
! @section 1.2
! @expect ok
! @description Section 7.2's example4: when routine2's error leaves it, the search for a recovery point naming 56 goes from the calling routine up the chain and finds main; routine1 is abandoned without running its own error handler (its UNDO handler runs), reading section 7.2's "abandoned without executing the error handler".
! @output routine2 handler
! @output routine1 undo
! @output main recovery point
! @exit 0
  PROC main()
    routine1;
    TPWrite "wrong: after routine1";
    ! Error recovery point
  ERROR (56)
    TPWrite "main recovery point";
    RETURN;
  ENDPROC
  PROC routine1()
    routine2;
    TPWrite "wrong: routine1 ends with normal execution";
  ERROR
    ! Another error handler
    TPWrite "wrong: routine1 handler";
    TRYNEXT;
  UNDO
    TPWrite "routine1 undo";
  ENDPROC
  PROC routine2()
    RAISE 56;
  ERROR
    TPWrite "routine2 handler";
    ! This will propagate the error 56 to main
    RAISE;
  ENDPROC
ENDMODULE
