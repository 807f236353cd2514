MODULE settings
! @format 2
! @section 2.20
! @expect semantic-error b.mod:2:12
! @description Two global objects declared in two different modules of the task buffer may not share a name; refused at the one in the later file.
  VAR num total;
ENDMODULE
