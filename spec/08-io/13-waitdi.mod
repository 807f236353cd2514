MODULE waitdi_case
! @format 3
! @section 13
! @expect ok
! @io io/basic.io
! @statement-time 0
! @description WaitDI waits until the input has the value: the clock jumps to the stimulus event that sets it (1 s); a wait whose condition already holds ends at once (WaitDO).
! @output di1 is 1 after 1000
! @output di1 is 0 after 2000
! @output do2 is 1 after 2000
  VAR clock c;
  PROC main()
    ClkStart c;
    WaitDI di1, 1;
    TPWrite "di1 is 1 after " \Num:=Round(ClkRead(c) * 1000);
    WaitDI di1, 0;
    TPWrite "di1 is 0 after " \Num:=Round(ClkRead(c) * 1000);
    WaitDO do2, 1;
    TPWrite "do2 is 1 after " \Num:=Round(ClkRead(c) * 1000);
  ENDPROC
ENDMODULE
