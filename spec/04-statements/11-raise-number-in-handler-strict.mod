MODULE raise_number_in_handler_strict
! @format 2
! @section 4.11
! @expect semantic-error 10:5
! @options strict
! @description Under --strict (doc/dialect.md), the manual's rule: a RAISE with an error number may not appear in an error handler; refused at RAISE.
  PROC main()
    DebugBreak;
  ERROR
    RAISE 12;
  ENDPROC
ENDMODULE
