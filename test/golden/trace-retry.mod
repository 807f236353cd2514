MODULE Cell
  VAR num divisor := 0;
  VAR num a{3} := [10, 20, 30];
  PROC main()
    VAR num q;
    q := a{2} / divisor;
    TPWrite "q = " \Num:=q;
  ERROR
    IF ERRNO = ERR_DIVZERO THEN
      divisor := 4;
      RETRY;
    ENDIF
  ENDPROC
ENDMODULE
