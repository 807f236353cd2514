MODULE sin_use
! @format 3
! @section 13
! @expect ok
! @description Sin takes its angle in degrees (installed-facts.md section 1).
! @output TRUE
! @output TRUE
! @output TRUE
! @exit 0
  PROC main()
    TPWrite "" \Bool:=Abs(Sin(30) - 0.5) < 0.0001;
    TPWrite "" \Bool:=Abs(Sin(90) - 1) < 0.0001;
    TPWrite "" \Bool:=Abs(Sin(-30) + 0.5) < 0.0001;
  ENDPROC
ENDMODULE
