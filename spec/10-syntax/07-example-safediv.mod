MODULE example_safediv
! @section 7.1
! @expect ok
! @description The example of section 7.1.
  VAR num max_num := 1E30;
  FUNC num safediv(num x, num y)
    RETURN x / y;
  ERROR
    IF ERRNO = ERR_DIVZERO THEN
      ! return max numeric value
      RETURN max_num;
    ENDIF
  ENDFUNC
ENDMODULE
