MODULE conditional_expression
! @section 3.4
! @expect ok
! @description The example of section 3.4 as the condition of IF and WHILE.
  VAR num counter;
  VAR num level;
  PROC main()
    IF counter > 5 OR level < 0 THEN
      counter := 0;
    ENDIF
    WHILE counter > 5 OR level < 0 DO
      counter := 0;
    ENDWHILE
  ENDPROC
ENDMODULE
