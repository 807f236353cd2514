MODULE acos_use
! @format 3
! @section 13
! @expect ok
! @description ACos gives an angle in degrees, from 0 to 180.
! @output TRUE
! @output TRUE
! @exit 0
  PROC main()
    TPWrite "" \Bool:=Abs(ACos(0.5) - 60) < 0.001;
    TPWrite "" \Bool:=Abs(ACos(-1) - 180) < 0.001;
  ENDPROC
ENDMODULE
