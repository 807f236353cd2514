MODULE trynext_if_condition
! @format 3
! @section 4.14
! @section 7.2
! @expect ok
! @description An error inside a function called in an IF condition: the IF is the statement that caused it (section 7.2), so TRYNEXT continues after ENDIF, running neither branch.
! @output handler
! @output after if
! @exit 0
  FUNC bool check()
    RAISE 3;
  ENDFUNC
  PROC main()
    IF check() THEN
      TPWrite "then";
    ELSE
      TPWrite "else";
    ENDIF
    TPWrite "after if";
  ERROR
    TPWrite "handler";
    TRYNEXT;
  ENDPROC
ENDMODULE
