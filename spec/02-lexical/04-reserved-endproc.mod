MODULE reserved_endproc
! @section 2.4
! @expect syntax-error 5:11
! @description The reserved word ENDPROC cannot be used as an identifier.
  VAR num ENDPROC;
ENDMODULE
