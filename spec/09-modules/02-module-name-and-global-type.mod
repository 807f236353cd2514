MODULE gripper
! @format 2
! @section 9.2
! @section 2.12
! @expect semantic-error 7:10
! @description A module and a global type may not share a name; refused at the record's name.
  RECORD gripper
    num force;
  ENDRECORD
ENDMODULE
