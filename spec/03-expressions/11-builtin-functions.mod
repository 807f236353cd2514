MODULE builtin_functions
! @format 2
! @section 3.11
! @section 11
! @expect ok
! @description The built-in functions of chapter 11: Dim, Present, IsPers and IsVar.
  VAR num table{4, 5};
  VAR num n;
  PERS num total := 0;
  PROC main()
    n := Dim(table, 1) * Dim(table, 2);
    probe total;
    probe n;
  ENDPROC
  PROC probe(INOUT num x \num extra)
    IF IsPers(x) AND Present(extra) THEN
      x := extra;
    ELSEIF IsVar(x) THEN
      x := 0;
    ENDIF
  ENDPROC
ENDMODULE
