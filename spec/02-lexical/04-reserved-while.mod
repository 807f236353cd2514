MODULE reserved_while
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word WHILE cannot be used as an identifier.
  VAR num WHILE;
ENDMODULE
