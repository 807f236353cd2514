MODULE function_argument_conditional_pl
! @section 3.11
! @expect syntax-error 7:17
! @description A conditional function argument names a <parameter>; <VAR> is allowed in procedure calls only.
  VAR num x;
  PROC main()
    x := f(\a ? <VAR>);
  ENDPROC
ENDMODULE
