MODULE reserved_if
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word IF cannot be used as an identifier.
  VAR num IF;
ENDMODULE
