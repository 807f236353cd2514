MODULE reserved_endfor
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word ENDFOR cannot be used as an identifier.
  VAR num ENDFOR;
ENDMODULE
