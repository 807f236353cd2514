MODULE reserved_elseif
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word ELSEIF cannot be used as an identifier.
  VAR num ELSEIF;
ENDMODULE
