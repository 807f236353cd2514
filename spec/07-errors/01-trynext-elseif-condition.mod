MODULE trynext_elseif_condition
! @format 3
! @section 4.14
! @section 4.16
! @section 7.1
! @expect ok
! @description An error in the condition of a second ELSEIF: TRYNEXT goes on after the whole IF statement (section 4.14: the statement after the one that caused the error), not into an ELSE list.
! @output handler
! @output after
! @output retries 1
! @exit 0
  VAR num n := 0;
  VAR num retries;
  PROC main()
    IF n = 1 THEN
      TPWrite "one";
    ELSEIF n = 2 THEN
      TPWrite "two";
    ELSEIF 1 / n > 0 THEN
      TPWrite "positive";
    ELSE
      TPWrite "else";
    ENDIF
    TPWrite "after";
    IF n = 1 THEN
      TPWrite "one";
    ELSEIF 1 / n > 0 THEN
      TPWrite "positive";
    ENDIF
  ERROR
    IF retries = 0 THEN
      TPWrite "handler";
      retries := 1;
      TRYNEXT;
    ENDIF
    TPWrite "retries " \Num:=retries;
    RETURN;
  ENDPROC
ENDMODULE
