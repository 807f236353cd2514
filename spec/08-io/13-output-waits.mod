MODULE output_waits
! @format 3
! @section 13
! @expect ok
! @io io/basic.io
! @statement-time 0
! @description WaitGO and WaitAO wait on outputs that a trap sets (at 0.5 s); \ValueAtTimeout (WaitAI) gets the input's value when \MaxTime runs out; SetDO \Sync changes the output before the next instruction; GInputDnum reads a group input as a dnum.
! @output go1=4 at 500
! @output ao1 above 2 at 500
! @output ai1 at timeout TRUE
! @output sync 1
! @output dnum TRUE
  VAR intnum t;
  VAR clock c;
  VAR num at_timeout := -1;
  TRAP set_outputs
    SetGO go1, 4;
    SetAO ao1, 2.5;
  ENDTRAP
  PROC main()
    ClkStart c;
    CONNECT t WITH set_outputs;
    ITimer \Single, 0.5, t;
    WaitGO go1, 4;
    TPWrite "go1=" + NumToStr(GOutput(go1), 0) + " at " + NumToStr(Round(ClkRead(c) * 1000), 0);
    WaitAO ao1 \GT, 2;
    TPWrite "ao1 above 2 at " \Num:=Round(ClkRead(c) * 1000);
    WaitAI ai1 \GT, 100 \MaxTime:=0.5 \ValueAtTimeout:=at_timeout;
  ERROR
    IF ERRNO = ERR_WAIT_MAXTIME THEN
      TPWrite "ai1 at timeout " \Bool:=(at_timeout = 2.5);
      SetDO \Sync, do1, 1;
      TPWrite "sync " \Num:=do1;
      TPWrite "dnum " \Bool:=(GInputDnum(gi1) = 5);
      RETURN;
    ENDIF
  ENDPROC
ENDMODULE
