MODULE loop_b
! @task T_B
  PROC main()
    TPWrite "B 1";
    TPWrite "B 2";
    TPWrite "B 3";
    TPWrite "B 4";
  ENDPROC
ENDMODULE
