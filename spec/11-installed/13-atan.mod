MODULE atan_use
! @format 3
! @section 13
! @expect ok
! @description ATan gives an angle in degrees, from -90 to 90.
! @output TRUE
! @output TRUE
! @exit 0
  PROC main()
    TPWrite "" \Bool:=Abs(ATan(1) - 45) < 0.001;
    TPWrite "" \Bool:=Abs(ATan(-1) + 45) < 0.001;
  ENDPROC
ENDMODULE
