MODULE error_in_function_stops
! @format 3
! @section 7.1
! @expect ok
! @description With no handler anywhere, an error inside a function is reported at the statement of the function where it occurred, not at the call.
! @exit 1
! @error ERR_DIVZERO 9:5
  FUNC num inverse(num x)
    RETURN 1 / x;
  ENDFUNC
  PROC main()
    VAR num y;
    y := inverse(0);
  ENDPROC
ENDMODULE
