MODULE palletizer
! @format 2
! @section 9.2
! @section 5.3
! @expect semantic-error b.mod:1:8
! @description A global routine and a module of the task may not share a name; the module, declared in the later file, is refused at its name.
  VAR num layers;
ENDMODULE
