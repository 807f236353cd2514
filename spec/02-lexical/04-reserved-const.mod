MODULE reserved_const
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word CONST cannot be used as an identifier.
  VAR num CONST;
ENDMODULE
