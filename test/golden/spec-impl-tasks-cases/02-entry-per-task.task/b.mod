MODULE entry_b
! @task T_B
  PROC main()
    TPWrite "B main";
  ENDPROC
  PROC serve()
    TPWrite "B serve";
  ENDPROC
ENDMODULE
