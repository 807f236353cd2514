MODULE hand_shake_b
! @task T_B
  PERS num state;
  PROC main()
    WaitUntil state = 1;
    TPWrite "B saw 1";
    state := 2;
    WaitUntil state = 3;
    TPWrite "B saw 3";
  ENDPROC
ENDMODULE
