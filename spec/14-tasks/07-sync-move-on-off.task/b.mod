MODULE syncmove_b
! @task T_B
  VAR syncident sync_on;
  VAR syncident sync_off;
  PERS tasks all_tasks{2};
  PROC main()
    TPWrite "B before " \Bool := IsSyncMoveOn();
    SyncMoveOn sync_on, all_tasks;
    TPWrite "B on " \Bool := IsSyncMoveOn();
    SyncMoveOff sync_off;
    TPWrite "B off " \Bool := IsSyncMoveOn();
  ENDPROC
ENDMODULE
