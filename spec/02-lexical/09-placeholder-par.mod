MODULE placeholder_par
! @section 2.9
! @section 5.2
! @expect ok
! @description <PAR> stands for a parameter declaration, first or after a comma.
  PROC p1(<PAR>)
  ENDPROC
  PROC p2(num a, <PAR>, <PAR>)
  ENDPROC
ENDMODULE
