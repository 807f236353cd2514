MODULE sync_b
! @task T_B
  VAR syncident meet;
  PERS tasks both{2};
  PROC main()
    TPWrite "B arrives";
    WaitSyncTask meet, both;
    TPWrite "B goes";
    WaitTime 2;
    WaitSyncTask meet, both;
    TPWrite "B again";
  ENDPROC
ENDMODULE
