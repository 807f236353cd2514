MODULE clock_b
! @task T_B
  PROC main()
    WaitTime 1;
    TPWrite "B after 1 s";
  ENDPROC
ENDMODULE
