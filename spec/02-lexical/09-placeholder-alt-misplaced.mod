MODULE placeholder_alt_misplaced
! @section 2.9
! @expect syntax-error 5:10
! @description <ALT> stands only after a backslash or a bar of an optional parameter declaration.
  PROC p(<ALT>)
  ENDPROC
ENDMODULE
