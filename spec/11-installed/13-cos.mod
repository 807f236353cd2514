MODULE cos_use
! @format 3
! @section 13
! @expect ok
! @description Cos takes its angle in degrees.
! @output TRUE
! @output TRUE
! @output TRUE
! @exit 0
  PROC main()
    TPWrite "" \Bool:=Abs(Cos(60) - 0.5) < 0.0001;
    TPWrite "" \Bool:=Abs(Cos(0) - 1) < 0.0001;
    TPWrite "" \Bool:=Abs(Cos(180) + 1) < 0.0001;
  ENDPROC
ENDMODULE
