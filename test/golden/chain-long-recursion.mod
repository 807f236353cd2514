MODULE chain_long
  PROC rec(num n)
    VAR num x;
    IF n > 0 THEN
      rec n - 1;
    ELSE
      x := 1 / 0;
    ENDIF
  ERROR
    RAISE;
  ENDPROC
  PROC main()
    rec 9000;
  ENDPROC
ENDMODULE
