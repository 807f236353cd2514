MODULE reserved_endmodule
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word ENDMODULE cannot be used as an identifier.
  VAR num ENDMODULE;
ENDMODULE
