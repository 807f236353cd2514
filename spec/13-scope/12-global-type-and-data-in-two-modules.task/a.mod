MODULE settings
! @format 2
! @section 2.12
! @section 2.20
! @expect semantic-error b.mod:2:11
! @description A global type and a global data object in different modules may not share a name; refused at the later one.
  RECORD gripdata
    num force;
  ENDRECORD
ENDMODULE
