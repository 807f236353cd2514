MODULE chain_mutual
  ! Two routines calling each other, 31 calls under main: a chain of 32 routines.
  PROC ping(num n)
    VAR num x;
    IF n > 0 THEN
      pong n - 1;
    ELSE
      x := 1 / 0;
    ENDIF
  ERROR
    RAISE;
  ENDPROC
  PROC pong(num n)
    ping n - 1;
  ERROR
    RAISE;
  ENDPROC
  PROC main()
    ping 29;
  ENDPROC
ENDMODULE
