MODULE run_unknown_data
  PROC main()
    VAR num n;
    n := tool_weight + 1;
  ENDPROC
ENDMODULE
