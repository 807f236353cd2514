MODULE task_pers_b
! @task T_B
  TASK PERS num mine := 1;
  LOCAL PERS num here := 10;
  PROC main()
    WaitTime 0.01;
    TPWrite "B reads " + NumToStr(mine, 0) + " and " + NumToStr(here, 0);
  ENDPROC
ENDMODULE
