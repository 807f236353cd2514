MODULE run_memory_budget
  VAR num grid{100, 100};
  PROC main()
    TPWrite "started";
  ENDPROC
ENDMODULE
