MODULE user_module
! @format 3
! @section 7.4
! @expect ok
! @statement-time 0
! @io io/procerr.io
! @description The example of section 7.4 with ProcerrRecovery \SyncOrgMoveInst: the error belongs to the first MoveL, whose path the robot was on, and is raised in my_process at once (4.85 s) while the program pointer waits in write_log; write_log is not abandoned (its UNDO does not run, nor its error handler): my_process handles the error, restarts the path (StartMove, 4.85 s, no pause) and its RETRY goes on from where the program pointer is, in write_log's WaitTime (R-7.4-m); the first MoveL is not executed again. write_log ends at 5.3 s and the second MoveL is planned then: the robot had to begin the corner at p2 at 4.9 s, so p2 became a stop point (Z-failure, reached at 5 s) and the 100 mm at v100 run from 5.3 s to 6.3 s.
! @output write_log at 4800
! @output ERR_PATH_STOP in my_process at 4850
! @output done at 6300
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR intnum proc_sup_int;
  VAR clock clk;
  PROC main()
    MoveJ p1, v1000, fine, tool0;
    ClkStart clk;
    my_process;
    TPWrite "done at " \Num:=Round(1000 * ClkRead(clk));
  ENDPROC
  PROC my_process()
    my_proc_on;
    MoveL p2, v100, z10, tool0;
    write_log;
    MoveL Offs(p2, 0, 0, 100), v100, fine, tool0;
    my_proc_off;
  ERROR
    IF ERRNO = ERR_PATH_STOP THEN
      TPWrite "ERR_PATH_STOP in my_process at " \Num:=Round(1000 * ClkRead(clk));
      my_proc_on;
      StartMove;
      RETRY;
    ENDIF
  ENDPROC
  PROC write_log()
    TPWrite "write_log at " \Num:=Round(1000 * ClkRead(clk));
    WaitTime 0.5;
  ERROR
    TPWrite "not this handler";
  UNDO
    TPWrite "write_log abandoned";
  ENDPROC
  TRAP iprocfail
    my_proc_off;
    ProcerrRecovery \SyncOrgMoveInst;
    RETURN;
  ENDTRAP
  PROC my_proc_on()
    SetDO do_myproc, 1;
    CONNECT proc_sup_int WITH iprocfail;
    ISignalDI di_proc_sup, 1, proc_sup_int;
  ENDPROC
  PROC my_proc_off()
    SetDO do_myproc, 0;
    IDelete proc_sup_int;
  ENDPROC
ENDMODULE
