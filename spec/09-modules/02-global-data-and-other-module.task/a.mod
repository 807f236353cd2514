MODULE conveyor
! @format 2
! @section 9.2
! @expect semantic-error b.mod:2:11
! @description A global data object may not have the name of another module of the task; refused at the object in the later file.
  VAR num speed;
ENDMODULE
