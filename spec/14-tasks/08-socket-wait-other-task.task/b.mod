MODULE socket_wait_b
! @task T_B
  VAR clock c;
  PROC main()
    ClkStart c;
    WaitTime 0.2;
    TPWrite "B after " \Num := Round(ClkRead(c) \Dec := 1);
  ENDPROC
ENDMODULE
