MODULE two_routines_one_module
! @format 2
! @section 5.3
! @expect semantic-error 8:12
! @description Two routines of one module may not share a name, whatever their kinds; the second is refused at its name.
  PROC reset()
  ENDPROC
  FUNC num reset()
    RETURN 0;
  ENDFUNC
ENDMODULE
