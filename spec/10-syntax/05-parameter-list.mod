MODULE parameter_list
! @section 5.2
! @expect ok
! @description Every form of <first parameter declaration> and <next parameter declaration>.
  PROC p1(num a)
  ENDPROC
  PROC p2(num a, num b \num c, \num d, <PAR>)
  ENDPROC
  PROC p3(\num a, num b)
  ENDPROC
  PROC p4(<PAR>, <PAR>)
  ENDPROC
ENDMODULE
