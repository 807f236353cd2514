MODULE skipwarn_alone
! @format 3
! @section 7.5
! @expect ok
! @description SkipWarn withdraws the warning of the error its handler handles (section 7.5); outside an error handler there is none to withdraw, and it changes nothing: no error, ERRNO and the retry count as they were (doc/rulings.md R-7.5-m).
! @exit 0
! @output errno same TRUE
! @output tries 3
  VAR num tries := 0;
  VAR errnum before;
  PROC attempt()
    tries := tries + 1;
    IF tries < 3 RAISE 7;
  ENDPROC
  PROC main()
    before := ERRNO;
    SkipWarn;
    TPWrite "errno same " \Bool:=(ERRNO = before);
    attempt;
    TPWrite "tries " \Num:=tries;
  ERROR
    SkipWarn;
    SkipWarn;
    RETRY;
  ENDPROC
ENDMODULE
