MODULE syncmove_undo_a
! @format 4
! @task T_ROB1
! @section 14
! @section 7
! @expect ok
! @description SyncMoveUndo ends synchronized movement at once, without a synchronisation point (R-14-m), as in an UNDO handler: an error leaves work, whose UNDO handler runs SyncMoveUndo, and main's handler finds the task in independent movement. SyncMoveUndo in independent movement does nothing. B, which has no robot, cannot move in synchronized movement either (ERR_NOT_MOVETASK, handled, \ID or not), and leaves synchronized movement with SyncMoveUndo as well, meeting no one. A's first turn is the call of work, so B reaches SyncMoveOn first and waits; A, arriving last, goes on first.
! @output A on TRUE
! @output B on TRUE
! @output A undone FALSE
! @output B cannot move TRUE
! @output again FALSE
! @output B undone FALSE
  VAR syncident sync_on;
  PERS tasks all_tasks{2} := [["T_ROB1"], ["T_B"]];
  VAR num zero := 0;
  PROC main()
    work;
  ERROR
    TPWrite "A undone " \Bool := IsSyncMoveOn();
    SyncMoveUndo;
    TPWrite "again " \Bool := IsSyncMoveOn();
    RETURN;
  ENDPROC
  PROC work()
    VAR num x;
    SyncMoveOn sync_on, all_tasks;
    TPWrite "A on " \Bool := IsSyncMoveOn();
    x := 1 / zero;
  UNDO
    SyncMoveUndo;
  ENDPROC
ENDMODULE
