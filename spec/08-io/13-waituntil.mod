MODULE waituntil_case
! @format 3
! @section 13
! @expect ok
! @io io/basic.io
! @statement-time 0
! @description WaitUntil evaluates its condition again at every poll, 0.1 s by default (installed-facts.md section 4) or \PollRate: the input set at 1 s is seen at the poll at 1 s, the group input set at 3 s at the poll at 3 s (every 0.4 s from 1 s); \MaxTime \TimeFlag as for WaitDI; a condition that holds at once sets the flag FALSE.
! @output seen at 1000
! @output gi1 seen at 3000
! @output timed out TRUE
! @output at 3300
! @output timed out FALSE
! @output at 3300
  VAR clock c;
  VAR bool late;
  PROC main()
    ClkStart c;
    WaitUntil di1 = 1;
    TPWrite "seen at " \Num:=Round(ClkRead(c) * 1000);
    WaitUntil GInput(gi1) = 12 \PollRate:=0.4;
    TPWrite "gi1 seen at " \Num:=Round(ClkRead(c) * 1000);
    WaitUntil di1 = 1 \MaxTime:=0.3 \TimeFlag:=late;
    TPWrite "timed out " \Bool:=late;
    TPWrite "at " \Num:=Round(ClkRead(c) * 1000);
    WaitUntil di2 = 1 \MaxTime:=1 \TimeFlag:=late;
    TPWrite "timed out " \Bool:=late;
    TPWrite "at " \Num:=Round(ClkRead(c) * 1000);
  ENDPROC
ENDMODULE
