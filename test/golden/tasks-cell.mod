MODULE tasks_cell
  ! A second task that agrees with tasks-robot.mod on every shared persistent.
  PERS num counts{3};
  PERS bool ready;
  PERS string state;
  VAR syncident meet;
  PERS tasks both{2};
  PROC main()
    state := "busy";
    ready := TRUE;
    WaitSyncTask meet, both;
  ENDPROC
ENDMODULE
