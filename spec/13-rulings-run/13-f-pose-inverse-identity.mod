MODULE rulings_pose_identity
! @format 3
! @section 13
! @section 2.14
! @expect ok
! @description R-13-f: PoseInv(p) = [-(R(rot)^T trans), conjugate of rot], PoseMult(p1, p2) = [trans1 + R(rot1) trans2, rot1 * rot2] and PoseVect(p, v) = R(rot) v + trans, so PoseMult(p, PoseInv(p)) and PoseMult(PoseInv(p), p) are the identity pose; [0,0,0,1] turns 180 degrees about z.
! @output PoseInv trans=[10,20,-30]
! @output PoseInv rot=[0,0,0,-1]
! @output p*inv trans=[0,0,0]
! @output p*inv rot=[1,0,0,0]
! @output inv*p trans=[0,0,0]
! @output inv*p rot=[1,0,0,0]
! @output PoseVect=[9,-2,3]
! @output PoseMult trans=[9,-2,3]
! @output PoseMult rot=[0,0,1,0]
! @exit 0
  PROC main()
    VAR pose p := [[10, 20, 30], [0, 0, 0, 1]];
    VAR pose h := [[10, 0, 0], [0, 0, 0, 1]];
    VAR pose q := [[1, 2, 3], [0, 1, 0, 0]];
    VAR pose inv;
    VAR pose r;
    inv := PoseInv(p);
    TPWrite "PoseInv trans=" \Pos:=inv.trans;
    TPWrite "PoseInv rot=" \Orient:=inv.rot;
    r := PoseMult(p, inv);
    TPWrite "p*inv trans=" \Pos:=r.trans;
    TPWrite "p*inv rot=" \Orient:=r.rot;
    r := PoseMult(inv, p);
    TPWrite "inv*p trans=" \Pos:=r.trans;
    TPWrite "inv*p rot=" \Orient:=r.rot;
    TPWrite "PoseVect=" \Pos:=PoseVect(h, [1, 2, 3]);
    r := PoseMult(h, q);
    TPWrite "PoseMult trans=" \Pos:=r.trans;
    TPWrite "PoseMult rot=" \Orient:=r.rot;
  ENDPROC
ENDMODULE
