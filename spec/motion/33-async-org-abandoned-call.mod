MODULE user_module
! @format 3
! @section 7.4
! @expect ok
! @statement-time 0
! @io io/procerr-second-call.io
! @description Section 7.4, "error when my_process has ended", with \\SyncOrgMoveInst: main calls my_process twice; the process fails at 9.85 s, when the robot is still on the first call's MoveL to p1 (its segment ends at 9.9 s, the corner) and the program pointer waits in the second call's first MoveL (planned at 9.8 s, PP-flyby). The first call was abandoned, so "the error is raised in main" (one step up), not in the second call's handler; main's handler restarts the path and RETRY goes on where the program pointer is (R-7.4-m): the second call's MoveL to p2 (p2 at 15 s, the program pointer on at 14.8 s) and MoveL to p1 (the program pointer on at 19.8 s).
! @output ERR_PATH_STOP in main at 9850
! @output done at 19800
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR intnum proc_sup_int;
  VAR clock clk;
  PROC main()
    MoveJ p1, v1000, fine, tool0;
    ClkStart clk;
    my_process;
    my_process;
    TPWrite "done at " \Num:=Round(1000 * ClkRead(clk));
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
    MoveL p1, v100, z10, tool0;
    my_proc_off;
  ERROR
    IF ERRNO = ERR_PATH_STOP THEN
      TPWrite "ERR_PATH_STOP in my_process at " \Num:=Round(1000 * ClkRead(clk));
      StartMove;
      RETRY;
    ENDIF
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
