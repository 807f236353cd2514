MODULE routine_data_and_label
! @format 2
! @section 2.20
! @section 4.4
! @expect semantic-error 9:5
! @description A routine data object and a label of the same routine may not share a name; the label is refused at its name.
  PROC main()
    VAR num next;
    next:
  ENDPROC
ENDMODULE
