MODULE tpwrite_dnum
! @format 3
! @section 13
! @expect ok
! @description TPWrite \Dnum writes a dnum; an integer value is written without decimals.
! @output d=250
! @output d=-3
! @exit 0
  PROC main()
    VAR dnum d := 250;
    TPWrite "d=" \Dnum:=d;
    d := -3;
    TPWrite "d=" \Dnum:=d;
  ENDPROC
ENDMODULE
