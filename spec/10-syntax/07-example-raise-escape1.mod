MODULE example_raise_escape1
! @section 7.1
! @expect ok
! @description The RAISE example of section 7.1, its elided parts completed into a function.
  CONST errnum escape1 := 10;
  VAR num val2 := 2;
  FUNC num f()
    RAISE escape1;
  ERROR
    IF ERRNO = escape1 THEN
      RETURN val2;
    ENDIF
  ENDFUNC
ENDMODULE
