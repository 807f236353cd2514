MODULE served_after_last
! @format 3
! @section 8
! @expect ok
! @statement-time 0.1
! @description An interrupt is served after the last statement of a statement list (chapter 8), before the statement after it is entered: queued while interrupts are disabled, it is served when IEnable, the last statement of the IF's list, has run, at 0.9 s; at the entry of the next statement it would be 1.0 s, that statement's time charged first.
! @output a T b
! @output trap at 0.9
  VAR intnum t;
  VAR clock c;
  VAR num seen := -1;
  VAR string log := "";
  TRAP tick
    seen := ClkRead(c \HighRes);
    log := log + " T";
  ENDTRAP
  PROC main()
    ClkStart c;
    IDisable;
    CONNECT t WITH tick;
    ITimer \Single, 0.05, t;
    WaitTime 0.1;
    IF TRUE THEN
      log := log + " a";
      IEnable;
    ENDIF
    log := log + " b";
    TPWrite StrPart(log, 2, StrLen(log) - 1);
    TPWrite "trap at " \Num:=seen;
  ENDPROC
ENDMODULE
