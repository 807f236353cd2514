MODULE function_call_leading_comma
! @section 3.11
! @expect syntax-error 7:12
! @description A function argument list does not begin with a comma.
  VAR num x;
  PROC main()
    x := f(, 1);
  ENDPROC
ENDMODULE
