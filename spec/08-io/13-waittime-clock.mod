MODULE waittime_clock
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @description WaitTime advances the virtual clock by exactly its time; ClkRead reads a running clock, ClkStop stops it, ClkReset stops it and sets it to 0 (doc/rulings.md R-8-g); WaitTime \InPos waits for no motion (doc/rulings.md R-8-b).
! @output 1500 ms
! @output stopped 1500
! @output started again 2000
! @output reset 0
! @output InPos 0
  VAR clock c;
  PROC main()
    ClkStart c;
    WaitTime 1.5;
    TPWrite NumToStr(Round(ClkRead(c) * 1000), 0) + " ms";
    ClkStop c;
    WaitTime 1;
    TPWrite "stopped " \Num:=Round(ClkRead(c) * 1000);
    ClkStart c;
    WaitTime 0.5;
    TPWrite "started again " \Num:=Round(ClkRead(c \HighRes) * 1000);
    ClkReset c;
    WaitTime 1;
    TPWrite "reset " \Num:=Round(ClkRead(c) * 1000);
    ClkStart c;
    WaitTime \InPos, 0;
    TPWrite "InPos " \Num:=Round(ClkRead(c) * 1000);
  ENDPROC
ENDMODULE
