MODULE reserved_connect
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word CONNECT cannot be used as an identifier.
  VAR num CONNECT;
ENDMODULE
