MODULE raise_number_in_handler
! @format 2
! @section 4.11
! @section 7.1
! @expect ok
! @description Dialect (doc/dialect.md, R-4.11-handler1): a RAISE with an error number in an error handler, as ABB's add-ins write it, is accepted without --strict, directly and nested in an IF.
  CONST errnum ERR_MINE := 12;
  PROC main()
    DebugBreak;
  ERROR
    IF ERRNO = ERR_DIVZERO RAISE ERR_MINE;
    RAISE 13;
  ENDPROC
ENDMODULE
