MODULE parameter_list_placeholder_witho
! @section 5.2
! @expect syntax-error 5:16
! @description After the first parameter <PAR> is preceded by ','.
  PROC p(num a <PAR>)
  ENDPROC
ENDMODULE
