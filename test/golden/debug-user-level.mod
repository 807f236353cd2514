MODULE debug_user_level
  VAR num divisor := 0;
  PROC main()
    TPWrite "start";
    Scale 10;
    TPWrite "after scale";
    Guarded;
    TPWrite "end";
  ERROR
    TPWrite "main handler " \Num:=ERRNO;
    divisor := 5;
    RETRY;
  ENDPROC
  PROC Guarded()
    Fragile;
    TPWrite "after Fragile";
  ERROR
    TPWrite "guarded handler " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE
