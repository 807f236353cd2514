MODULE reserved_endif
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word ENDIF cannot be used as an identifier.
  VAR num ENDIF;
ENDMODULE
