MODULE inomax_b
! @task T_B
  VAR intnum ints{101};
  VAR num n := 0;
  TRAP t
  ENDTRAP
  PROC main()
    WaitTime 1;
    FOR i FROM 1 TO 101 DO
      CONNECT ints{i} WITH t;
      n := n + 1;
    ENDFOR
  ERROR
    TPWrite "B connected " + NumToStr(n, 0) + " ERR_INOMAX " \Bool:=(ERRNO = ERR_INOMAX);
    RETURN;
  ENDPROC
ENDMODULE
