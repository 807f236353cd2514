MODULE posevect_use
! @format 3
! @section 13
! @expect ok
! @description PoseVect(Pose, Pos) transforms a point: the pose's rotation applied to it, plus the pose's translation; a half turn about z maps [1,0,0] to [-1,0,0].
! @output 0
! @output 2
! @output 3
! @exit 0
  PROC main()
    VAR pose frame := [[1, 2, 3], [0, 0, 0, 1]];
    VAR pos point := [1, 0, 0];
    VAR pos r;
    r := PoseVect(frame, point);
    TPWrite "" \Num:=r.x;
    TPWrite "" \Num:=r.y;
    TPWrite "" \Num:=r.z;
  ENDPROC
ENDMODULE
