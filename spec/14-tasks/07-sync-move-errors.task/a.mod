MODULE syncmove_err_a
! @format 4
! @task T_ROB1
! @section 14
! @section 7
! @expect ok
! @description The errors of synchronized movement (R-14-m): SyncMoveOn \TimeOut whose tasks do not all arrive in time raises ERR_SYNCMOVEON; a task list naming a task that is not a task of the run, ERR_TASKNAME; SyncMoveOff in independent movement, ERR_SYNCMOVEOFF; SyncMoveOn in synchronized movement, ERR_SYNCMOVEON; SyncMoveOff \TimeOut whose tasks do not arrive in time, ERR_SYNCMOVEOFF, and the task stays in synchronized movement; a negative \TimeOut, ERR_ARGVALERR. Every one is handled.
! @output on timed out FALSE
! @output ERR_TASKNAME
! @output off without on
! @output on twice TRUE
! @output off timed out TRUE
! @output negative time-out
  VAR syncident s1;
  VAR syncident s2;
  VAR syncident s3;
  VAR syncident s4;
  PERS tasks both{2} := [["T_ROB1"], ["T_B"]];
  PERS tasks wrong{2} := [["T_ROB1"], ["T_NONE"]];
  PROC main()
    on_timeout;
    on_wrong;
    off_without_on;
    on_twice;
    off_timeout;
    negative_timeout;
  ENDPROC
  PROC on_timeout()
    SyncMoveOn s1, both \TimeOut := 1;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_SYNCMOVEON TPWrite "on timed out " \Bool := IsSyncMoveOn();
    RETURN;
  ENDPROC
  PROC on_wrong()
    SyncMoveOn s2, wrong;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_TASKNAME TPWrite "ERR_TASKNAME";
    RETURN;
  ENDPROC
  PROC off_without_on()
    SyncMoveOff s2;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_SYNCMOVEOFF TPWrite "off without on";
    RETURN;
  ENDPROC
  PROC on_twice()
    SyncMoveOn s3, both;
    SyncMoveOn s3, both;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_SYNCMOVEON TPWrite "on twice " \Bool := IsSyncMoveOn();
    RETURN;
  ENDPROC
  PROC off_timeout()
    SyncMoveOff s4 \TimeOut := 1;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_SYNCMOVEOFF TPWrite "off timed out " \Bool := IsSyncMoveOn();
    RETURN;
  ENDPROC
  PROC negative_timeout()
    SyncMoveUndo;
    SyncMoveOn s1, both \TimeOut := -1;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_ARGVALERR TPWrite "negative time-out";
    RETURN;
  ENDPROC
ENDMODULE
