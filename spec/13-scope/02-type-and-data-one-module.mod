MODULE type_and_data_one_module
! @format 2
! @section 2.12
! @section 2.20
! @expect semantic-error 10:11
! @description A type and a data object of one module may not share a name; the data object is refused at its name.
  RECORD sample
    num value;
  ENDRECORD
  VAR num sample;
ENDMODULE
