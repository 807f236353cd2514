MODULE syncmove_undo_b
! @task T_B
  VAR syncident sync_on;
  PERS tasks all_tasks{2};
  PROC main()
    SyncMoveOn sync_on, all_tasks;
    TPWrite "B on " \Bool := IsSyncMoveOn();
    try_move;
    SyncMoveUndo;
    TPWrite "B undone " \Bool := IsSyncMoveOn();
  ENDPROC
  PROC try_move()
    MoveAbsJ [[10, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]] \ID := 10, v100, fine, tool0;
  ERROR
    IF ERRNO = ERR_NOT_MOVETASK TPWrite "B cannot move " \Bool := IsSyncMoveOn();
    RETURN;
  ENDPROC
ENDMODULE
