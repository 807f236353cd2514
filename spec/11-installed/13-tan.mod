MODULE tan_use
! @format 3
! @section 13
! @expect ok
! @description Tan takes its angle in degrees.
! @output TRUE
! @output TRUE
! @exit 0
  PROC main()
    TPWrite "" \Bool:=Abs(Tan(45) - 1) < 0.0001;
    TPWrite "" \Bool:=Abs(Tan(-45) + 1) < 0.0001;
  ENDPROC
ENDMODULE
