MODULE data_called_as_procedure
! @format 2
! @section 4.6
! @expect semantic-error 8:5
! @description A data object is no procedure; refused at the name.
  VAR num counter;
  PROC main()
    counter;
  ENDPROC
ENDMODULE
