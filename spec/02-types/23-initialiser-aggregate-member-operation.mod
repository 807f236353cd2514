MODULE initialiser_aggregate_member
! @format 2
! @section 2.23
! @section 3.3
! @expect semantic-error 7:28
! @description Each member of a literal aggregate is a literal expression: 2 + 3 inside it is refused at its start.
  PERS pos refpnt := [100, 2 + 3, 0];
ENDMODULE
