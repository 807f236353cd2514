MODULE goto_data_object
! @format 2
! @section 4.7
! @expect semantic-error 8:10
! @description A GOTO to a name that is a variable, not a label; refused at the name.
  VAR num counter;
  PROC main()
    GOTO counter;
  ENDPROC
ENDMODULE
