MODULE raise_forms
! @format 2
! @section 4.11
! @section 7.1
! @expect ok
! @description Section 4.11's example: RAISE escape with a constant error number, and RAISE without a number in the error handler.
  CONST errnum escape := 10;
  VAR errnum ERR_MINE := -1;
  FUNC num lookup(num val1, num val2)
    IF val1 < 0 RAISE escape;
    IF val1 = 0 RAISE ERR_MINE;
    IF val1 > 100 RAISE 56;
    RETURN val1;
  ERROR
    IF ERRNO = escape THEN
      RETURN val2;
    ENDIF
    RAISE;
  ENDFUNC
ENDMODULE
