MODULE reserved_proc
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word PROC cannot be used as an identifier.
  VAR num PROC;
ENDMODULE
