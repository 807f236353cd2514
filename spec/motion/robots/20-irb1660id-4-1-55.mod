MODULE r_irb1660id_4_1_55
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @robot ROB1_1660_ID_1.55_4
! @description The ABB IRB 1660ID-4/1.55 of the robot library (doc/motion.md "The robot library", robots/irb1660id-4-1.55.robot), by its MOC.cfg robot type ROB1_1660_ID_1.55_4 (a controller backup's). A known pose: at the calibration position (all axes 0) the flange is at [a1 + d4 + d6, 0, d1 + a2 + a3] = [963.0, 0, 1296.5] (the product specification's dimensions). Reach: with axis 2 at 90 and axis 3 at -80.7845 (atan2(a3, d4) - 90) the arm is stretched forward (serial), the wrist centre (tool wc: tool0 moved back along its z by d6 = 135) at x = a1 + (a2 + sqrt(a3^2 + d4^2)) sin(axis 2) = 1536.8653, z = d1 + (a2 + sqrt(a3^2 + d4^2)) cos(axis 2) = 486.5000: the published reach 1550 mm within 2.5 %; a point 50 mm beyond the flange stretched level is out of reach (ERR_ROBLIMIT). Joint limits: axis 1 at its limit 180 moves, one degree beyond is refused (ERR_ROBLIMIT), as axis 3 one degree below -238. A move timed: axis 1 turning 45 degrees at its 180 degrees/s takes 45 / 180 = 0.250 s.
! @output home x 963.0 z 1296.5
! @output reach x 1536.9 z 486.5
! @output far ERR_ROBLIMIT
! @output edge 180.0
! @output beyond 1 ERR_ROBLIMIT
! @output beyond 3 ERR_ROBLIMIT
! @output t 0.250
  CONST jointtarget calib := [[0,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget stretched := [[0,90,-80.784523,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget edge := [[180,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget past1 := [[181,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget past3 := [[0,0,-239,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget turned := [[45,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget far := [[1721.8653,0,486.5],[0.707107,0,0.707107,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS tooldata wc := [TRUE,[[0,0,-135],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];
  VAR clock clk;
  VAR string what;
  PROC main()
    VAR pos p;
    VAR jointtarget j;
    MoveAbsJ calib, v1000, fine, tool0;
    p := CPos(\Tool:=tool0);
    TPWrite "home x " + NumToStr(p.x, 1) + " z " + NumToStr(p.z, 1);
    MoveAbsJ stretched, v1000, fine, tool0;
    p := CPos(\Tool:=wc);
    TPWrite "reach x " + NumToStr(p.x, 1) + " z " + NumToStr(p.z, 1);
    what := "far";
    MoveJ far, v1000, fine, tool0;
    MoveAbsJ edge, v1000, fine, tool0;
    j := CJointT();
    TPWrite "edge " + NumToStr(j.robax.rax_1, 1);
    what := "beyond 1";
    MoveAbsJ past1, v1000, fine, tool0;
    what := "beyond 3";
    MoveAbsJ past3, v1000, fine, tool0;
    MoveAbsJ calib, v1000, fine, tool0;
    ClkStart clk;
    MoveAbsJ turned, v5000, fine, tool0;
    TPWrite "t " + NumToStr(ClkRead(clk), 3);
  ERROR
    IF ERRNO = ERR_ROBLIMIT THEN
      TPWrite what + " ERR_ROBLIMIT";
      TRYNEXT;
    ENDIF
  ENDPROC
ENDMODULE
