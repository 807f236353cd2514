MODULE goto_into_if
! @format 2
! @section 4.7
! @expect semantic-error 8:10
! @description A GOTO may not jump into a statement list (section 4.7); a label inside IF is refused at the label name after GOTO.
  VAR num i;
  PROC main()
    GOTO inside;
    IF i > 0 THEN
      inside:
      i := 0;
    ENDIF
  ENDPROC
ENDMODULE
