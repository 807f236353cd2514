MODULE retry_count_reset
! @format 3
! @section 4.13
! @section 7.5
! @expect ok
! @description The retry limit counts the RETRYs of one failing statement: once a retried statement completes, the count starts again (doc/rulings.md R-7.2-b), so six errors in six iterations, each retried once, stay within the default limit of 4.
! @output 1
! @output 2
! @output 3
! @output 4
! @output 5
! @output 6
! @output retries=6
! @exit 0
  VAR num retries;
  VAR bool fail := TRUE;
  PROC main()
    VAR num x;
    FOR i FROM 1 TO 6 DO
      fail := TRUE;
      x := i / check();
      TPWrite "" \Num:=x;
    ENDFOR
    TPWrite "retries=" \Num:=retries;
  ERROR
    retries := retries + 1;
    fail := FALSE;
    RETRY;
  ENDPROC
  FUNC num check()
    IF fail RETURN 0;
    RETURN 1;
  ENDFUNC
ENDMODULE
