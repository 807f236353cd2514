MODULE raise_escape
! @format 3
! @section 7.1
! @section 4.11
! @expect ok
! @description Section 7.1's escape1 (and 4.11's escape): RAISE with a user error number leaves deeply nested code at once; the function's handler recognises the number and returns val2.
! @output 3
! @output 99
! @exit 0
  CONST errnum escape1 := 10;
  CONST num val2 := 99;
  FUNC num search(num wanted)
    FOR i FROM 1 TO 5 DO
      FOR j FROM 1 TO 5 DO
        IF i * j = wanted RETURN i;
        IF i * j > 20 RAISE escape1;
      ENDFOR
    ENDFOR
    RETURN 0;
  ERROR
    IF ERRNO = escape1 THEN
      RETURN val2;
    ENDIF
  ENDFUNC
  PROC main()
    TPWrite "" \Num:=search(12);
    TPWrite "" \Num:=search(23);
  ENDPROC
ENDMODULE
