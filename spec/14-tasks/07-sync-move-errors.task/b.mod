MODULE syncmove_err_b
! @task T_B
  VAR syncident s3;
  PERS tasks both{2};
  PROC main()
    WaitTime 1.5;
    SyncMoveOn s3, both;
  ENDPROC
ENDMODULE
