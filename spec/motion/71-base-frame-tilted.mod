MODULE base_frame_tilted
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @base-frame 0,0,1000,0,-0.707107,0.707107,0
! @description A robot hung from a frame: its base frame at [0,0,1000], turned 180 degrees about the axis (-1,1,0) (the quaternion [0,-0.707107,0.707107,0], MOC.cfg's -base_frame_orient_u0 .. u3 of a real cell; law F-base, R-bk-12), so that a point [x,y,z] of the base frame is [-y,-x,1000-z] in the world, and an orientation q of the base frame the base's quaternion times q. At the axes home the flange ([302,0,558], [0,0,1,0] in the base frame) is at [0,-302,442] in the world, its orientation [0.707107,0,0,0.707107] (90 degrees about z; q and -q are one orientation, so the case prints the magnitudes and that q1 and q4 have one sign). The world target p1 [-100,-302,542] with that orientation is [302,100,458] in the base frame: MoveL reaches it in 141.4 mm at v100 (1414 ms), axis 1 then at atan2(100, 302) = 18 degrees; CRobT and CPos read the world's coordinates back; an upright robot at the world's origin would stand 442 mm lower.
! @output home 0 -302 442 q 0.7071 0.0000 0.0000 0.7071 same sign TRUE
! @output t 1414 at -100 -302 542 axis1 18
! @output cpos -100 -302 542
  CONST jointtarget home := [[0,0,0,0,90,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p1 := [[-100,-302,542],[0.707107,0,0,0.707107],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  PROC main()
    VAR robtarget r;
    VAR jointtarget j;
    VAR pos p;
    MoveAbsJ home, v1000, fine, tool0;
    r := CRobT(\Tool:=tool0);
    TPWrite "home " + NumToStr(r.trans.x, 0) + " " + NumToStr(r.trans.y, 0) + " " + NumToStr(r.trans.z, 0) + " q " + NumToStr(Abs(r.rot.q1), 4) + " " + NumToStr(Abs(r.rot.q2), 4) + " " + NumToStr(Abs(r.rot.q3), 4) + " " + NumToStr(Abs(r.rot.q4), 4) + " same sign " \Bool := r.rot.q1 * r.rot.q4 > 0;
    ConfL \Off;
    ClkStart clk;
    MoveL p1, v100, fine, tool0;
    r := CRobT(\Tool:=tool0);
    j := CJointT();
    TPWrite "t " + NumToStr(Round(1000 * ClkRead(clk)), 0) + " at " + NumToStr(r.trans.x, 0) + " " + NumToStr(r.trans.y, 0) + " " + NumToStr(r.trans.z, 0) + " axis1 " + NumToStr(j.robax.rax_1, 0);
    p := CPos(\Tool:=tool0);
    TPWrite "cpos " + NumToStr(p.x, 0) + " " + NumToStr(p.y, 0) + " " + NumToStr(p.z, 0);
  ENDPROC
ENDMODULE
