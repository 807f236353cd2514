MODULE function_argument_placeholder_ex
! @section 3.11
! @expect syntax-error 7:12
! @description Function arguments are <expr>s: <EXP> is not one.
  VAR num x;
  PROC main()
    x := f(<EXP>);
  ENDPROC
ENDMODULE
