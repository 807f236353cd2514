MODULE tasks_cell_late
  ! A second task that sets ready and ends without reaching the meeting point: tasks-robot.mod
  ! waits at WaitSyncTask for a task that has ended, a deadlock.
  PERS bool ready;
  PROC main()
    ready := TRUE;
    TPWrite "cell done";
  ENDPROC
ENDMODULE
