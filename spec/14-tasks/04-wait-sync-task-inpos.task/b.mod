MODULE inpos_b
! @task T_B
  VAR syncident meet;
  PERS tasks both{2};
  PROC main()
    WaitSyncTask meet, both;
    TPWrite "B goes";
  ENDPROC
ENDMODULE
