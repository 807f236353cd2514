MODULE ipers_case
! @format 3
! @section 8
! @expect ok
! @statement-time 0
! @description IPers orders an interrupt each time the persistent gets a new value; storing the value it has already changes nothing.
! @output seen 2
  PERS num counter := 0;
  VAR intnum p;
  VAR num seen := 0;
  TRAP changed
    seen := seen + 1;
  ENDTRAP
  PROC main()
    counter := 0;
    CONNECT p WITH changed;
    IPers counter, p;
    counter := 1;
    counter := 1;
    counter := 2;
    WaitTime 0.1;
    TPWrite "seen " \Num:=seen;
  ENDPROC
ENDMODULE
