MODULE user_module
! @format 3
! @section 7.4
! @expect ok
! @statement-time 0
! @io io/procerr.io
! @output write_log at 4800
! @output ERR_PATH_STOP in my_process at 4850
! @output write_log abandoned
! @description Section 7.4, "if the error handler in my_process ends with EXIT, all program execution stops": the \SyncOrgMoveInst error (4.85 s, the program pointer in write_log) goes to my_process's handler, whose EXIT abandons every routine from where the program pointer is (write_log's UNDO runs, R-7.4-m) and ends the task; main's handler does not run.
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
      EXIT;
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
