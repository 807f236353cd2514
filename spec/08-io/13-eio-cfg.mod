MODULE eio_cfg
! @format 3
! @section 2.16
! @expect ok
! @io io/eio.cfg
! @statement-time 0
! @description The EIO_SIGNAL entries of a RobotWare EIO.cfg file declare the signals (-Name, -SignalType, -Default; an entry may go on over lines ending in a backslash); the other sections are not read.
! @output diStart=0
! @output doLamp=1
! @output goCode=200
  PROC main()
    TPWrite "diStart=" \Num:=diStart;
    TPWrite "doLamp=" \Num:=doLamp;
    SetGO goCode, 200;
    TPWrite "goCode=" \Num:=goCode;
  ENDPROC
ENDMODULE
