MODULE reserved_sysmodule
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word SYSMODULE cannot be used as an identifier.
  VAR num SYSMODULE;
ENDMODULE
