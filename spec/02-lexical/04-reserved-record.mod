MODULE reserved_record
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word RECORD cannot be used as an identifier.
  VAR num RECORD;
ENDMODULE
