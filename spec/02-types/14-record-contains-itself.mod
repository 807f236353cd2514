MODULE record_contains_itself
! @format 2
! @section 2.14
! @expect semantic-error 6:10
! @description A record that has a component of its own type has no finite value; it is refused at its name in the RECORD line.
  RECORD chain_link
    num value;
    chain_link next;
  ENDRECORD
ENDMODULE
