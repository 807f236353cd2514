MODULE reserved_test
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word TEST cannot be used as an identifier.
  VAR num TEST;
ENDMODULE
