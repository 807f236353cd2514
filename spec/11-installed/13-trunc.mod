MODULE trunc_use
! @format 3
! @section 13
! @expect ok
! @description Trunc cuts the decimals off, toward zero, keeping Dec of them (installed-facts.md section 1: Trunc(0.3852138\Dec:=3) is 0.385).
! @output TRUE
! @output 2
! @output -2
! @output 0
! @exit 0
  PROC main()
    TPWrite "" \Bool:=Abs(Trunc(0.3852138\Dec:=3) - 0.385) < 0.00001;
    TPWrite "" \Num:=Trunc(2.6);
    TPWrite "" \Num:=Trunc(-2.6);
    TPWrite "" \Num:=Trunc(0.3852138);
  ENDPROC
ENDMODULE
