MODULE setdo_sdelay
! @format 3
! @section 13
! @expect ok
! @io io/basic.io
! @statement-time 0
! @description SetDO \SDelay changes the output after the delay, and execution goes on at once.
! @output at once 0
! @output after 0.4 s 0
! @output after 0.6 s 1
  PROC main()
    SetDO \SDelay:=0.5, do1, 1;
    TPWrite "at once " \Num:=DOutput(do1);
    WaitTime 0.4;
    TPWrite "after 0.4 s " \Num:=do1;
    WaitTime 0.2;
    TPWrite "after 0.6 s " \Num:=do1;
  ENDPROC
ENDMODULE
