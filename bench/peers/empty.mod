MODULE bench_empty
  ! The start-up: a main that does nothing.
  PROC main()
  ENDPROC
ENDMODULE
