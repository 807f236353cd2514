MODULE orientzyx_use
! @format 3
! @section 13
! @expect ok
! @description OrientZYX(ZAngle, YAngle, XAngle) builds the quaternion of Euler angles in degrees (installed-facts.md section 4): no rotation is [1,0,0,0]; 90 degrees about z is [cos 45, 0, 0, sin 45].
! @output identity=TRUE
! @output z90=TRUE
! @exit 0
  PROC main()
    VAR orient o;
    o := OrientZYX(0, 0, 0);
    TPWrite "identity=" \Bool:=o = [1, 0, 0, 0];
    o := OrientZYX(90, 0, 0);
    TPWrite "z90=" \Bool:=Abs(o.q1 - 0.707107) < 0.0001 AND Abs(o.q2) < 0.0001 AND Abs(o.q3) < 0.0001 AND Abs(o.q4 - 0.707107) < 0.0001;
  ENDPROC
ENDMODULE
