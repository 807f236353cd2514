MODULE reserved_viewonly
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word VIEWONLY cannot be used as an identifier.
  VAR num VIEWONLY;
ENDMODULE
