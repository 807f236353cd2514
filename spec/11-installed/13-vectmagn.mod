MODULE vectmagn_use
! @format 3
! @section 13
! @expect ok
! @description VectMagn gives the length of a vector.
! @output 13
! @output 0
! @exit 0
  PROC main()
    VAR pos v := [3, 4, 12];
    VAR pos zero;
    TPWrite "" \Num:=VectMagn(v);
    TPWrite "" \Num:=VectMagn(zero);
  ENDPROC
ENDMODULE
