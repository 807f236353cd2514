MODULE function_call_missing_comma
! @section 3.11
! @expect syntax-error 7:14
! @description Required function arguments are separated by commas.
  VAR num x;
  PROC main()
    x := f(1 2);
  ENDPROC
ENDMODULE
