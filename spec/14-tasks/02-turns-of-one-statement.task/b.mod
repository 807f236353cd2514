MODULE turns_b
! @task T_B
  PROC main()
    TPWrite "b1";
    TPWrite "b2";
  ENDPROC
ENDMODULE
