MODULE poseinv_use
! @format 3
! @section 13
! @expect ok
! @description PoseInv gives the inverse frame: without rotation the translation is negated; with a half turn about z, the inverse turned back composes with the frame to the identity.
! @output pure translation=TRUE
! @output identity=TRUE
! @exit 0
  PROC main()
    VAR pose shift := [[1, 2, 3], [1, 0, 0, 0]];
    VAR pose turn := [[1, 2, 3], [0, 0, 0, 1]];
    VAR pose r;
    TPWrite "pure translation=" \Bool:=PoseInv(shift) = [[-1, -2, -3], [1, 0, 0, 0]];
    r := PoseMult(turn, PoseInv(turn));
    TPWrite "identity=" \Bool:=VectMagn(r.trans) < 0.0001 AND Abs(Abs(r.rot.q1) - 1) < 0.0001;
  ENDPROC
ENDMODULE
