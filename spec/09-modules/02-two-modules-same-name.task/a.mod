MODULE station
! @format 2
! @section 9.2
! @expect semantic-error b.mod:1:8
! @description Two different modules may not share a name; the module of the later file is refused at its name.
  VAR num a_count;
ENDMODULE
