MODULE argument_placeholder_in_call
! @format 2
! @section 5.2
! @section 2.9
! @expect ok
! @description A call of a routine whose parameter list holds <PAR> is not checked against it.
  PROC a(num x, <PAR>)
  ENDPROC
  PROC main()
    a 1, 2;
  ENDPROC
ENDMODULE
