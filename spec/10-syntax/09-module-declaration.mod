MODULE module_declaration
! @section 9.2
! @expect ok
! @description A module: type definitions, then data declarations, then routine declarations.
  RECORD r
    num a;
  ENDRECORD
  ALIAS num n;
  VAR r x;
  CONST n y := 1;
  PROC main()
  ENDPROC
  FUNC num f()
    RETURN y;
  ENDFUNC
ENDMODULE
