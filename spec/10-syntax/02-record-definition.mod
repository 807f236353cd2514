MODULE record_definition
! @section 2.14
! @expect ok
! @description The record definitions printed in sections 2.14 and 2.11 (the second on one line).
  RECORD newtype
    num x;
  ENDRECORD
  LOCAL RECORD object num usecount; string name; ENDRECORD
ENDMODULE
