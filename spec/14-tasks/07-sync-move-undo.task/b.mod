MODULE syncmove_undo_b
! @task T_B
  VAR syncident sync_on;
  PERS tasks all_tasks{2};
  PROC main()
    SyncMoveOn sync_on, all_tasks;
    TPWrite "B on " \Bool := IsSyncMoveOn();
    SyncMoveUndo;
    TPWrite "B undone " \Bool := IsSyncMoveOn();
  ENDPROC
ENDMODULE
