MODULE reserved_return
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word RETURN cannot be used as an identifier.
  VAR num RETURN;
ENDMODULE
