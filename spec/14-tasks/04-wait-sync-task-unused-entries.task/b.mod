MODULE sync_b
! @task T_B
  VAR syncident meet;
  PERS tasks cell{4};
  PROC main()
    TPWrite "B arrives";
    WaitSyncTask meet, cell;
    TPWrite "B goes";
  ENDPROC
ENDMODULE
