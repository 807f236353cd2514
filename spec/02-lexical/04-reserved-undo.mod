MODULE reserved_undo
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word UNDO cannot be used as an identifier.
  VAR num UNDO;
ENDMODULE
