MODULE ipers_b
! @task T_B
  PERS num shared;
  PROC main()
    WaitTime 0.5;
    TPWrite "B changes";
    shared := 5;
  ENDPROC
ENDMODULE
