MODULE goto_other_routine
! @format 2
! @section 4.7
! @section 4.4
! @expect semantic-error 8:10
! @description The scope of a label is its routine; a GOTO to a label of another routine is refused at the label name.
  PROC main()
    GOTO restart;
  ENDPROC
  PROC helper()
    restart:
  ENDPROC
ENDMODULE
