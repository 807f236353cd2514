MODULE statement_kinds
! @section 4.1
! @expect ok
! @description Every alternative of <statement>, <simple statement> and <compound statement>.
  VAR num x;
  VAR bool b;
  VAR intnum ino;
  PROC main()
    x := 1;
    p x;
    GOTO l;
    l:
    RETURN;
    RAISE;
    EXIT;
    RETRY;
    TRYNEXT;
    CONNECT ino WITH t;
    IF b THEN
    ENDIF
    IF b x := 2;
    FOR i FROM 1 TO 2 DO
      BREAK;
    ENDFOR
    WHILE b DO
      CONTINUE;
    ENDWHILE
    TEST x
    ENDTEST
    ! a comment
    <SMT>
  ENDPROC
ENDMODULE
