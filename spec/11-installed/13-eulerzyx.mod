MODULE eulerzyx_use
! @format 3
! @section 13
! @expect ok
! @description EulerZYX with \Z, \Y or \X gives that Euler angle of a rotation in degrees: it recovers the angles OrientZYX was given.
! @output z=TRUE
! @output y=TRUE
! @output x=TRUE
! @exit 0
  PROC main()
    VAR orient o;
    o := OrientZYX(30, 20, 10);
    TPWrite "z=" \Bool:=Abs(EulerZYX(\Z, o) - 30) < 0.001;
    TPWrite "y=" \Bool:=Abs(EulerZYX(\Y, o) - 20) < 0.001;
    TPWrite "x=" \Bool:=Abs(EulerZYX(\X, o) - 10) < 0.001;
  ENDPROC
ENDMODULE
