MODULE parameter_and_label_same_name
! @format 2
! @section 5.3
! @section 4.4
! @expect semantic-error 8:5
! @description A label may not have the name of a routine data object (a parameter) of its routine; refused at the label.
  PROC move_to(num retry_count)
    retry_count:
  ENDPROC
ENDMODULE
