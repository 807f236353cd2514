MODULE conditional_duplicate
! @format 3
! @section 3.11
! @section 5.2
! @section 12
! @expect ok
! @description Section 3.11: conditional arguments may go to mutually exclusive alternatives, "at most one of them may be present". check(\on ? high \off ? low) with one of high and low present passes that one; with both present it raises ERR_ARGDUPCND (chapter 12), at the call.
! @output on
! @output off
! @output neither
! @output both: argdupcnd
! @exit 0
  PROC check(\switch on | switch off)
    IF Present(on) THEN
      TPWrite "on";
    ELSEIF Present(off) THEN
      TPWrite "off";
    ELSE
      TPWrite "neither";
    ENDIF
  ENDPROC
  PROC pass(\switch high, \switch low)
    check \on ? high \off ? low;
  ENDPROC
  PROC main()
    pass \high;
    pass \low;
    pass;
    pass \high \low;
    TPWrite "wrong";
  ERROR
    IF ERRNO = ERR_ARGDUPCND TPWrite "both: argdupcnd";
    RETURN;
  ENDPROC
ENDMODULE
