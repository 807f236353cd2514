MODULE oracle_program
  VAR num total;
  FUNC num sq(num x)
    RETURN x * x;
  ENDFUNC
  PROC main()
    FOR i FROM 1 TO 3 DO
      total := total + sq(i);
      TPWrite "total " \Num:=total;
    ENDFOR
    total := total / 0;
  ERROR
    TPWrite "handled " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE
