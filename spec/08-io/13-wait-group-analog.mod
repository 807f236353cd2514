MODULE wait_group_analog
! @format 3
! @section 13
! @expect ok
! @io io/basic.io
! @statement-time 0
! @description WaitGI compares with = by default, or \NOTEQ, \LT, \GT; WaitAI with \LT or \GT; the clock jumps to the stimulus event that satisfies the comparison.
! @output gi1 not 5 at 3000
! @output gi1 > 10 at 3000
! @output ai1 > 5 at 4000
! @output ai1 < 10 at 4000
  VAR clock c;
  PROC main()
    ClkStart c;
    WaitGI gi1 \NOTEQ, 5;
    TPWrite "gi1 not 5 at " \Num:=Round(ClkRead(c) * 1000);
    WaitGI gi1 \GT, 10;
    TPWrite "gi1 > 10 at " \Num:=Round(ClkRead(c) * 1000);
    WaitAI ai1 \GT, 5;
    TPWrite "ai1 > 5 at " \Num:=Round(ClkRead(c) * 1000);
    WaitAI ai1 \LT, 10;
    TPWrite "ai1 < 10 at " \Num:=Round(ClkRead(c) * 1000);
  ENDPROC
ENDMODULE
