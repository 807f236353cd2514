MODULE huge_times
! @format 3
! @section 13
! @section 8
! @expect ok
! @io io/basic.io
! @statement-time 0
! @max-time 10
! @description Times as large as a num holds (3E38 s) are times that never come, not times in the past: a cyclic and a single timer of 3E38 s never fire, SetDO \SDelay:=3E38 never changes the output, WaitUntil \PollRate:=3E38 polls once and times out at its \MaxTime, and WaitTime 3E38 runs into the bound on virtual time (exit 3), like any wait beyond it (doc/rulings.md R-8-j).
! @output traps 0 do1 0
! @output flag TRUE at 2000
! @exit 3
  VAR intnum cyclic;
  VAR intnum single;
  VAR num n := 0;
  VAR bool flag;
  VAR clock clk;
  TRAP tick
    n := n + 1;
  ENDTRAP
  PROC main()
    ClkStart clk;
    CONNECT cyclic WITH tick;
    ITimer 3E38, cyclic;
    CONNECT single WITH tick;
    ITimer \Single, 3E38, single;
    SetDO \SDelay:=3E38, do1, 1;
    WaitTime 1;
    TPWrite "traps " + NumToStr(n, 0) + " do1 " + NumToStr(do1, 0);
    WaitUntil di2 = 0 \MaxTime:=1 \TimeFlag:=flag \PollRate:=3E38;
    TPWrite "flag " + ValToStr(flag) + " at " + NumToStr(Round(ClkRead(clk) * 1000), 0);
    WaitTime 3E38;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
