MODULE itimer_single
! @format 3
! @section 8
! @expect ok
! @statement-time 0
! @description ITimer \Single orders one interrupt only, Time seconds after the order; INTNO holds the number of the interrupt the trap serves (chapter 12).
! @output one tick TRUE
! @output count 1
  VAR intnum t1;
  VAR num n := 0;
  VAR bool same;
  TRAP tick
    n := n + 1;
    same := INTNO = t1;
  ENDTRAP
  PROC main()
    CONNECT t1 WITH tick;
    ITimer \Single, 0.5, t1;
    WaitTime 3;
    TPWrite "one tick " \Bool:=same;
    TPWrite "count " \Num:=n;
  ENDPROC
ENDMODULE
