MODULE raise_nested_in_handler_strict
! @format 2
! @section 4.11
! @expect semantic-error 10:28
! @options strict
! @description Under --strict (doc/dialect.md), the manual's rule: a RAISE with an error number nested in an IF of an error handler is in the handler; refused at RAISE.
  PROC main()
    DebugBreak;
  ERROR
    IF ERRNO = ERR_DIVZERO RAISE 12;
  ENDPROC
ENDMODULE
