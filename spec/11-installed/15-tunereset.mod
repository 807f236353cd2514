MODULE tunereset_accepted
! @format 3
! @section 11
! @expect ok
! @description TuneReset (ABB, RAPID Instructions: the servo tuning back to normal) is installed and accepted; the motion model has no servo tuning, so it changes nothing (doc/rulings.md R-13-motset1).
! @output reset
  PROC main()
    TuneReset;
    TPWrite "reset";
  ENDPROC
ENDMODULE
