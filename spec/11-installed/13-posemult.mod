MODULE posemult_use
! @format 3
! @section 13
! @expect ok
! @description PoseMult(Pose1, Pose2) composes two frames: the result's translation is Pose1's rotation applied to Pose2's translation, plus Pose1's translation; its rotation is the product of the rotations. A half turn about z ([0,0,0,1]) keeps the numbers integral.
! @output translations add=TRUE
! @output trans=[3,-1,3]
! @output rot=[0,0,0,1]
! @exit 0
  PROC main()
    VAR pose shift1 := [[1, 2, 3], [1, 0, 0, 0]];
    VAR pose shift2 := [[4, 5, 6], [1, 0, 0, 0]];
    VAR pose turn := [[1, 2, 3], [0, 0, 0, 1]];
    VAR pose move := [[-2, 3, 0], [1, 0, 0, 0]];
    VAR pose r;
    r := PoseMult(shift1, shift2);
    TPWrite "translations add=" \Bool:=r = [[5, 7, 9], [1, 0, 0, 0]];
    r := PoseMult(turn, move);
    TPWrite "trans=[" + NumToStr(r.trans.x, 0) + "," + NumToStr(r.trans.y, 0) + "," + NumToStr(r.trans.z, 0) + "]";
    IF r.rot = [0, 0, 0, 1] TPWrite "rot=[0,0,0,1]";
  ENDPROC
ENDMODULE
