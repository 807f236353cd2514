MODULE pulsedo_case
! @format 3
! @section 13
! @expect ok
! @io io/basic.io
! @statement-time 0
! @description PulseDO: a pulse of 0.2 s by default, or \PLength; a high output gets a low pulse, and \High makes the pulse high whatever the output was (doc/rulings.md R-8-d).
! @output pulse 1
! @output 0.3 s later 0
! @output long pulse 1
! @output 1.1 s later 0
! @output low pulse 0
! @output 0.3 s later 1
! @output high 1
! @output 0.3 s later 0
  PROC main()
    PulseDO do1;
    TPWrite "pulse " \Num:=do1;
    WaitTime 0.3;
    TPWrite "0.3 s later " \Num:=do1;
    PulseDO \PLength:=1, do1;
    WaitTime 0.5;
    TPWrite "long pulse " \Num:=do1;
    WaitTime 0.6;
    TPWrite "1.1 s later " \Num:=do1;
    PulseDO do2;
    TPWrite "low pulse " \Num:=do2;
    WaitTime 0.3;
    TPWrite "0.3 s later " \Num:=do2;
    PulseDO \High, do2;
    TPWrite "high " \Num:=do2;
    WaitTime 0.3;
    TPWrite "0.3 s later " \Num:=do2;
  ENDPROC
ENDMODULE
