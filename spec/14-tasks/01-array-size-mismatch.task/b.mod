MODULE size_b
! @task T_B
  PERS num arr{3};
  PROC main()
  ENDPROC
ENDMODULE
