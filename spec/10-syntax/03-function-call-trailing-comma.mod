MODULE function_call_trailing_comma
! @section 3.11
! @expect syntax-error 7:15
! @description ',' in a function argument list is followed by an argument.
  VAR num x;
  PROC main()
    x := f(1, );
  ENDPROC
ENDMODULE
