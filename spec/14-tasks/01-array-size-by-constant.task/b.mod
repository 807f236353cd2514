MODULE by_constant_b
! @task T_B
  PERS num arr{2};
  PROC main()
    TPWrite "B reads " \Num := arr{2};
  ENDPROC
ENDMODULE
