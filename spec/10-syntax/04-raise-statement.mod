MODULE raise_statement
! @section 4.11
! @section 7.1
! @expect ok
! @description The example of sections 4.11 and 7.1, its elided parts completed into a function.
  CONST errnum escape := 10;
  VAR num val2 := 2;
  FUNC num f()
    RAISE escape; ! recover from this position
    RAISE 56;
    RETURN 0;
  ERROR
    IF ERRNO = escape THEN
      RETURN val2;
    ENDIF
    RAISE;
  ENDFUNC
ENDMODULE
