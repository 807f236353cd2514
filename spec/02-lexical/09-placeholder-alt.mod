MODULE placeholder_alt
! @section 2.9
! @section 5.2
! @expect ok
! @description <ALT> stands for an alternative of an optional parameter declaration.
  PROC p1(\<ALT>)
  ENDPROC
  PROC p2(num a \switch on | <ALT> | num b, \<ALT> | <ALT>)
  ENDPROC
ENDMODULE
