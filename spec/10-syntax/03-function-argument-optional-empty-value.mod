MODULE function_argument_optional_empty
! @section 3.11
! @expect syntax-error 7:18
! @description An optional function argument with ':=' needs an expression.
  VAR num x;
  PROC main()
    x := f(\a := );
  ENDPROC
ENDMODULE
