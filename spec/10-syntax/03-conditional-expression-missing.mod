MODULE conditional_expression_missing
! @section 3.4
! @expect syntax-error 7:8
! @description IF needs a conditional expression before THEN.
  VAR num counter;
  PROC main()
    IF THEN
      counter := 0;
    ENDIF
  ENDPROC
ENDMODULE
