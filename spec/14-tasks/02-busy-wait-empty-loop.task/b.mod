MODULE busy_b
! @task T_B
  PERS num flag;
  PROC main()
    TPWrite "B 1";
    TPWrite "B 2";
    flag := 1;
    TPWrite "B 3";
    TPWrite "B 4";
  ENDPROC
ENDMODULE
