MODULE long_jump_example2
! @format 3
! @section 7.2
! @expect ok
! @description Section 7.2's example2: routine2 raises 56, its own handler propagates it with RAISE; the search for a recovery point starts at the calling routine (routine1, no handler) and finds main's ERROR (56), whose RETRY calls routine1 again (routine2 raises only the first time here).
! @output routine2 handler 56
! @output main recovery point 56
! @output routine2 done
! @output main done
! @exit 0
  VAR num raised;
  PROC main()
    routine1;
    TPWrite "main done";
    ! Error recovery point
  ERROR (56)
    TPWrite "main recovery point " \Num:=ERRNO;
    RETRY;
  ENDPROC
  PROC routine1()
    routine2;
  ENDPROC
  PROC routine2()
    IF raised = 0 THEN
      raised := 1;
      RAISE 56;
    ENDIF
    TPWrite "routine2 done";
  ERROR
    TPWrite "routine2 handler " \Num:=ERRNO;
    ! This will propagate the error 56 to main
    RAISE;
  ENDPROC
ENDMODULE
