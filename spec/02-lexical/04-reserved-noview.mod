MODULE reserved_noview
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word NOVIEW cannot be used as an identifier.
  VAR num NOVIEW;
ENDMODULE
