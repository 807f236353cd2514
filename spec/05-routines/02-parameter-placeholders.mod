MODULE parameter_placeholders
! @format 2
! @section 5.2
! @section 2.9
! @expect ok
! @description <PAR>, <ALT> and <DIM> stand for undefined parts of parameter lists without a semantic error.
  PROC a(num x, <PAR>)
  ENDPROC
  PROC b(\num y | <ALT>)
  ENDPROC
  PROC c(num z{<DIM>})
  ENDPROC
ENDMODULE
