MODULE pow_use
! @format 3
! @section 13
! @expect ok
! @description Pow(Base, Exponent) gives Base to the power Exponent.
! @output 1024
! @output TRUE
! @output TRUE
! @exit 0
  PROC main()
    TPWrite "" \Num:=Pow(2, 10);
    TPWrite "" \Bool:=Abs(Pow(9, 0.5) - 3) < 0.0001;
    TPWrite "" \Bool:=Abs(Pow(2, -2) - 0.25) < 0.0001;
  ENDPROC
ENDMODULE
