MODULE goto_unknown_label
! @format 2
! @section 4.7
! @expect semantic-error 7:10
! @description A GOTO to a label that does not exist; refused at the label name.
  PROC main()
    GOTO nowhere;
  ENDPROC
ENDMODULE
