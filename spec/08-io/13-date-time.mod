MODULE date_time
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @max-time 100000
! @description CDate, CTime and GetTime read a virtual wall clock: the epoch (default 2024-01-01 00:00:00, a Monday) plus the virtual time, so that runs are reproducible.
! @output 2024-01-01 00:00:00
! @output 2024-01-02 01:01:01
! @output wday 2
! @output hour 1
! @output min 1
! @output sec 1
  PROC main()
    TPWrite CDate() + " " + CTime();
    WaitTime 90061;
    TPWrite CDate() + " " + CTime();
    TPWrite "wday " \Num:=GetTime(\WDay);
    TPWrite "hour " \Num:=GetTime(\Hour);
    TPWrite "min " \Num:=GetTime(\Min);
    TPWrite "sec " \Num:=GetTime(\Sec);
  ENDPROC
ENDMODULE
