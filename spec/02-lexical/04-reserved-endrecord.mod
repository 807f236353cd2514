MODULE reserved_endrecord
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word ENDRECORD cannot be used as an identifier.
  VAR num ENDRECORD;
ENDMODULE
