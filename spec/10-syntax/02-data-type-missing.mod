MODULE data_type_missing
! @section 2.11
! @expect syntax-error 5:8
! @description A data declaration names a data type and then the object: "VAR x;" has no object name.
  VAR x;
ENDMODULE
