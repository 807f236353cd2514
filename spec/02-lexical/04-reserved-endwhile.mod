MODULE reserved_endwhile
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word ENDWHILE cannot be used as an identifier.
  VAR num ENDWHILE;
ENDMODULE
