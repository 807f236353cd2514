MODULE rulings_orientzyx_eulerzyx
! @format 3
! @section 13
! @expect ok
! @description R-13-f: OrientZYX(z, y, x) = qz * qy * qx in degrees (about z, then the new y, then the new x), so OrientZYX(90,0,90) is [0.5,0.5,0.5,0.5] and not [0.5,0.5,-0.5,0.5]; EulerZYX gives the matching angles back.
! @output OrientZYX(0,0,0)=[1,0,0,0]
! @output OrientZYX(180,0,0)=[0,0,0,1]
! @output OrientZYX(0,180,0)=[0,0,1,0]
! @output OrientZYX(0,0,180)=[0,1,0,0]
! @output OrientZYX(90,0,0)=[0.707107,0,0,0.707107]
! @output OrientZYX(90,0,90)=[0.5,0.5,0.5,0.5]
! @output Z=TRUE Y=TRUE X=TRUE
! @output Z=TRUE Y=TRUE X=TRUE
! @exit 0
  FUNC bool near(num a, num b)
    RETURN Abs(a - b) < 0.001;
  ENDFUNC

  PROC main()
    VAR orient o;
    TPWrite "OrientZYX(0,0,0)=" \Orient:=OrientZYX(0, 0, 0);
    TPWrite "OrientZYX(180,0,0)=" \Orient:=OrientZYX(180, 0, 0);
    TPWrite "OrientZYX(0,180,0)=" \Orient:=OrientZYX(0, 180, 0);
    TPWrite "OrientZYX(0,0,180)=" \Orient:=OrientZYX(0, 0, 180);
    TPWrite "OrientZYX(90,0,0)=" \Orient:=OrientZYX(90, 0, 0);
    TPWrite "OrientZYX(90,0,90)=" \Orient:=OrientZYX(90, 0, 90);
    o := OrientZYX(30, 20, 10);
    TPWrite "Z=" + ValToStr(near(EulerZYX(\Z, o), 30)) + " Y=" + ValToStr(near(EulerZYX(\Y, o), 20)) + " X=" + ValToStr(near(EulerZYX(\X, o), 10));
    o := [0.5, 0.5, 0.5, 0.5];
    TPWrite "Z=" + ValToStr(near(EulerZYX(\Z, o), 90)) + " Y=" + ValToStr(near(EulerZYX(\Y, o), 0)) + " X=" + ValToStr(near(EulerZYX(\X, o), 90));
  ENDPROC
ENDMODULE
