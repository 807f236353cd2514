MODULE hello
  VAR num count := 3;
  PROC main()
    VAR num i;
    TPWrite "Hello";
    FOR i FROM 1 TO count DO
      TPWrite "i = " \Num:=i;
    ENDFOR
    WHILE count > 0 DO
      count := count - 1;
    ENDWHILE
    TPWrite "count " \Num:=count;
    TPWrite "div " \Num:=safediv(10, 0);
    IF count = 0 TPWrite "zero";
  ENDPROC
  FUNC num safediv(num x, num y)
    RETURN x / y;
  ERROR
    IF ERRNO = ERR_DIVZERO THEN
      RETURN 99;
    ENDIF
  ENDFUNC
ENDMODULE
