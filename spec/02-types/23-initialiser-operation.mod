MODULE initialiser_operation
! @format 2
! @section 2.23
! @section 3.3
! @expect semantic-error 7:19
! @description A literal expression holds a single literal or aggregate: 2 * 3 is refused at its start.
  PERS num six := 2 * 3;
ENDMODULE
