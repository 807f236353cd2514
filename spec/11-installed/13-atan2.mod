MODULE atan2_use
! @format 3
! @section 13
! @expect ok
! @description ATan2(Y, X) gives the angle of the point (X, Y) in degrees, from -180 to 180, so the quadrant follows from the signs.
! @output TRUE
! @output TRUE
! @output TRUE
! @exit 0
  PROC main()
    TPWrite "" \Bool:=Abs(ATan2(1, -1) - 135) < 0.001;
    TPWrite "" \Bool:=Abs(ATan2(-1, -1) + 135) < 0.001;
    TPWrite "" \Bool:=Abs(ATan2(1, 1) - 45) < 0.001;
  ENDPROC
ENDMODULE
