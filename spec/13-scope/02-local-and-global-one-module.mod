MODULE local_and_global_one_module
! @format 2
! @section 2.20
! @expect semantic-error 7:17
! @description A LOCAL and a global object in the same module are still two module objects of that module; the second is refused at its name.
  VAR num counter;
  LOCAL VAR num counter;
ENDMODULE
