MODULE sync_timeout_b
! @task T_B
  PERS tasks both{2};
  PROC main()
    WaitTime 5;
  ENDPROC
ENDMODULE
