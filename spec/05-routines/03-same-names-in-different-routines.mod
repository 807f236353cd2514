MODULE same_names_in_different_routines
! @format 2
! @section 5.3
! @section 2.20
! @expect ok
! @description Parameters, routine data and labels of different routines do not clash.
  PROC first(num speed)
    VAR num count;
    again:
  ENDPROC
  PROC second(num speed)
    VAR num count;
    again:
  ENDPROC
  FUNC num third(num speed)
    CONST num count := 1;
    RETURN speed + count;
  ENDFUNC
ENDMODULE
