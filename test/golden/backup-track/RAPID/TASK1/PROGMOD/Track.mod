MODULE Track
  ! The robot rides the track TRACK_1 of MOC.cfg (R-bk-15): eax_a moves its base along the x axis
  ! of the track's base frame, turned 180 degrees about z, so along the world's -x.
  PROC main()
    VAR robtarget p;
    VAR jointtarget j;
    MoveAbsJ [[0,0,0,0,30,0],[0,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;
    p := CRobT(\Tool:=tool0 \WObj:=wobj0);
    TPWrite "track at 0: x " \Num:=Round(p.trans.x \Dec:=1);
    MoveAbsJ [[0,0,0,0,30,0],[1000,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;
    p := CRobT(\Tool:=tool0 \WObj:=wobj0);
    j := CJointT();
    TPWrite "track at 1000: x " \Num:=Round(p.trans.x \Dec:=1);
    TPWrite "eax_a " \Num:=j.extax.eax_a;
    MoveL Offs(p, 0, 0, 0), v1000, fine, tool0;
    TPWrite "a world target after the track moved: reached";
    MoveAbsJ [[0,0,0,0,30,0],[4000,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;
  ERROR
    TPWrite "beyond the track's travel: " \Num:=ERRNO;
    RETURN;
  ENDPROC
ENDMODULE
