MODULE placeholder_arg_misplaced
! @section 2.9
! @expect syntax-error 7:12
! @description <ARG> stands only in a procedure call, not in a function call.
  VAR num x;
  PROC main()
    x := f(<ARG>);
  ENDPROC
ENDMODULE
