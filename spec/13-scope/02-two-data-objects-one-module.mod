MODULE two_data_objects_one_module
! @format 2
! @section 2.20
! @section 2.12
! @expect semantic-error 8:13
! @description Two module objects declared in the same module may not have the same name; the second is refused at its name.
  VAR num counter;
  CONST num counter := 1;
ENDMODULE
