MODULE user_module
! @format 3
! @section 7.4
! @expect ok
! @statement-time 0
! @io io/procerr.io
! @description Section 7.4, "if the error handler in my_process ends with RAISE, the error is handled by the error handler in main; the program calls my_process and abandons write_log; if the handler in main ends with RETRY, my_process runs again": the \\SyncOrgMoveInst error (4.85 s, the program pointer in write_log) goes to my_process's handler, whose RAISE abandons write_log (its UNDO runs, R-7.4-m) and my_process; main's handler restarts the path and RETRYs the call: my_process runs again from its start at 4.85 s: its first MoveL, to p2 where the robot arrives at 5 s, has no length, so its zone shrinks to nothing (Z-clip) and the program pointer goes on at 4.9 s, the look-ahead before the robot reaches p2 (PP-flyby); write_log waits 0.5 s, and the second MoveL (100 mm at v100, fine) runs from 5.4 s to 6.4 s.
! @output write_log at 4800
! @output ERR_PATH_STOP in my_process at 4850
! @output write_log abandoned
! @output ERR_PATH_STOP in main at 4850
! @output write_log at 4900
! @output done at 6400
! @output at z 400
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR intnum proc_sup_int;
  VAR clock clk;
  PROC main()
    VAR pos here;
    MoveJ p1, v1000, fine, tool0;
    ClkStart clk;
    my_process;
    TPWrite "done at " \Num:=Round(1000 * ClkRead(clk));
    here := CPos(\Tool:=tool0);
    TPWrite "at z " \Num:=Round(here.z);
  ERROR
    IF ERRNO = ERR_PATH_STOP THEN
      TPWrite "ERR_PATH_STOP in main at " \Num:=Round(1000 * ClkRead(clk));
      StartMove;
      RETRY;
    ENDIF
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
      RAISE;
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
