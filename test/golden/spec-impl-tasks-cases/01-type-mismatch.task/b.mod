MODULE mismatch_b
! @task T_B
  PERS bool state;
  PROC main()
  ENDPROC
ENDMODULE
