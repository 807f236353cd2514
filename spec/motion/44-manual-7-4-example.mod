MODULE user_module
! @format 3
! @section 7.4
! @expect ok
! @statement-time 0
! @io io/procerr-manual.io
! @description The example program of section 7.4 as printed (its "HOME: " read as "HOME:", its Write with the comma the syntax needs), with the data it uses, a start point, and TPWrite lines added to show what happens. my_process runs twice; in the first call the process fails at 1.2 s while the robot moves to p2 (MoveL p1: 300 mm at v300, the program pointer on at 0.867 s; write_log; MoveL p2: 150 mm, the program pointer waits in it until 1.367 s). The trap turns the process off and calls ProcerrRecovery \\SyncLastMoveInst: the error is raised at that MoveL, my_process's handler turns the process on, StartMove (no pause) and RETRY: the move goes on as planned. The second call runs without error: MoveL p1 (150 mm back, the program pointer on at 1.867 s), write_log, MoveL p2: the program pointer leaves my_process at 2.367 s. The log file holds two lines.
! @output ERR_PATH_STOP at 1200
! @output done at 2367
! @output my_process executing
! @output my_process executing
  CONST robtarget p0 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p1 := [[300,50,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,50,450],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS tooldata tool1 := [TRUE,[[0,0,0],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];
  VAR clock clk;
  VAR intnum proc_sup_int;
  VAR iodev logfile;
  PROC main()
    MoveJ p0, v1000, fine, tool1;
    ClkStart clk;
    my_process;
    my_process;
    TPWrite "done at " \Num:=Round(1000 * ClkRead(clk));
    Open "HOME:" \File:= "log.txt", logfile \Read;
    TPWrite ReadStr(logfile);
    TPWrite ReadStr(logfile);
    Close logfile;
  ERROR
  ENDPROC
  PROC my_process()
    my_proc_on;
    MoveL p1, v300, z10, tool1;
    write_log;
    MoveL p2, v300, z10, tool1;
    my_proc_off;
  ERROR
    IF ERRNO = ERR_PATH_STOP THEN
      TPWrite "ERR_PATH_STOP at " \Num:=Round(1000 * ClkRead(clk));
      my_proc_on;
      StartMove;
      RETRY;
    ENDIF
  ENDPROC
  PROC write_log()
    Open "HOME:" \File:= "log.txt", logfile \Append;
    Write logfile, "my_process executing";
    Close logfile;
  ERROR
    IF ERRNO = ERR_FILEOPEN THEN
      TRYNEXT;
    ENDIF
  UNDO
    Close logfile;
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
