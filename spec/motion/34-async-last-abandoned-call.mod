MODULE user_module
! @format 3
! @section 7.4
! @expect ok
! @statement-time 0
! @io io/procerr-second-call.io
! @description Section 7.4, "error when my_process has ended", with \SyncLastMoveInst: as spec/motion/33, the process fails at 9.85 s with the robot still on the first call's path and the program pointer waiting in the second call's first MoveL; the error goes to the move instruction being executed, so the second call's error handler handles it (main's does not); its RETRY of the MoveL does not plan it again but waits for the rest of its path (R-7.4-b), which StartMove restarted at once: the same times as without the error.
! @output ERR_PATH_STOP in my_process at 9850
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
    ProcerrRecovery \SyncLastMoveInst;
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
