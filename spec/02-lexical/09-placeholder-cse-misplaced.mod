MODULE placeholder_cse_misplaced
! @section 2.9
! @expect syntax-error 8:5
! @description <CSE> belongs to a TEST statement, not to IF.
  VAR bool b;
  PROC main()
    IF b THEN
    <CSE>
    ENDIF
  ENDPROC
ENDMODULE
