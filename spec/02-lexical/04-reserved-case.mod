MODULE reserved_case
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word CASE cannot be used as an identifier.
  VAR num CASE;
ENDMODULE
