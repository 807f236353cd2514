MODULE aggregate_placeholder
! @section 3.10
! @expect syntax-error 7:17
! @description Aggregate elements are <expr>s: <EXP> is not one.
  VAR pos p;
  PROC main()
    p := [1, 2, <EXP>];
  ENDPROC
ENDMODULE
