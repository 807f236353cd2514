MODULE goto_between_branches
! @format 2
! @section 4.7
! @expect semantic-error 9:12
! @description A GOTO from the THEN list to a label of the ELSE list jumps into another statement list; refused at the label name.
  VAR num i;
  PROC main()
    IF i > 0 THEN
      GOTO other;
    ELSE
      other:
      i := 1;
    ENDIF
  ENDPROC
ENDMODULE
