MODULE operator_timeout
! @format 3
! @section 13
! @expect ok
! @operator 13-operator-timeout.operator
! @description An answer "timeout" in the operator's script: the operator does not answer (doc/rulings.md R-13-ui2). A procedure's dialogue waits \MaxTime of virtual time and ends with ERR_TP_MAXTIME, in \BreakFlag when it is given (the program goes on, the answer unchanged), else raised; a function's ends at once with the same error. \PersBoolBreak TRUE when the dialogue begins breaks it with ERR_TP_PERSBOOLBREAK, and takes no answer; \BreakFlag is 0 after a dialogue answered.
! @output Go on?
! @output flag TRUE
! @output key 9
! @output after 2
! @output maxtime in handler
! @output after 5
! @output entry maxtime 0
! @output persbool TRUE
! @output result 0
! @output Count?
! @output flag 04
  PERS bool stop_dialogue := TRUE;
  PROC main()
    VAR num key := 9;
    VAR errnum flag;
    VAR btnres answer := 3;
    VAR num n := 5;
    VAR clock c;
    ClkStart c;
    TPReadFK key, "Go on?", "Yes", "No", stEmpty, stEmpty, stEmpty \MaxTime:=2 \BreakFlag:=flag;
    TPWrite "flag " \Bool:=flag = ERR_TP_MAXTIME;
    TPWrite "key " \Num:=key;
    TPWrite "after " \Num:=Round(ClkRead(c));
    UIMsgBox "Start?" \Buttons:=btnYesNo \Result:=answer \MaxTime:=3;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_TP_MAXTIME THEN
      TPWrite "maxtime in handler";
      TPWrite "after " \Num:=Round(ClkRead(c));
      n := UINumEntry(\Message:="Parts" \InitValue:=1 \MaxTime:=10 \BreakFlag:=flag);
      TPWrite "entry maxtime " \Num:=Round(ClkRead(c)) - 5;
      answer := UIMessageBox(\Message:="Go?" \PersBoolBreak:=stop_dialogue \BreakFlag:=flag);
      TPWrite "persbool " \Bool:=flag = ERR_TP_PERSBOOLBREAK;
      TPWrite "result " \Num:=answer;
      stop_dialogue := FALSE;
      answer := UIMessageBox(\Message:="Go?" \PersBoolBreak:=stop_dialogue \BreakFlag:=flag);
      TPReadNum n, "Count?" \BreakFlag:=flag;
      TPWrite "flag " + NumToStr(flag, 0) \Num:=n;
      RETURN;
    ENDIF
  ENDPROC
ENDMODULE
