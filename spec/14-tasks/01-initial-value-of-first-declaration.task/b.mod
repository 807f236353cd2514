MODULE first_value_b
! @task T_B
  PERS num tool := 7;
  PERS num count := 5;
  PROC main()
    TPWrite "B tool " + NumToStr(tool, 0) + " count " + NumToStr(count, 0);
  ENDPROC
ENDMODULE
