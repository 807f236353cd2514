MODULE no_value_b
! @task T_B
  PERS num state;
  PERS bool flag;
  PROC main()
    TPWrite "B " + NumToStr(state, 0) + " " \Bool := flag;
  ENDPROC
ENDMODULE
