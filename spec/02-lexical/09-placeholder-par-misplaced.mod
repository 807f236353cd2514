MODULE placeholder_par_misplaced
! @section 2.9
! @expect syntax-error 5:18
! @description <PAR> cannot be an alternative of an optional parameter (that is <ALT>).
  PROC p(num a, \<PAR>)
  ENDPROC
ENDMODULE
