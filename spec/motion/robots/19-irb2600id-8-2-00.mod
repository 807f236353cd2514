MODULE r_irb2600id_8_2_00
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @robot ROB1_2600ID_2.00_8
! @description The ABB IRB 2600ID-8/2.00 of the robot library (doc/motion.md "The robot library", robots/irb2600id-8-2.00.robot), by its MOC.cfg robot type ROB1_2600ID_2.00_8 (a controller backup's). A known pose: at the calibration position (all axes 0) the flange is at [a1 + d4 + d6, 0, d1 + a2 + a3] = [1288.0, 0, 1495.0] (the product specification's dimensions). Reach: with axis 2 at 90 and axis 3 at -80.9145 (atan2(a3, d4) - 90) the arm is stretched forward (serial), the wrist centre (tool wc: tool0 moved back along its z by d6 = 200) at x = a1 + (a2 + sqrt(a3^2 + d4^2)) sin(axis 2) = 1999.9179, z = d1 + (a2 + sqrt(a3^2 + d4^2)) cos(axis 2) = 445.0000: the published reach 2000 mm within 2.5 %; a point 50 mm beyond the flange stretched level is out of reach (ERR_ROBLIMIT). Joint limits: axis 1 at its limit 180 moves, one degree beyond is refused (ERR_ROBLIMIT), as axis 3 one degree below -180. A move timed: axis 1 turning 45 degrees at its 175 degrees/s takes 45 / 175 = 0.257 s.
! @output home x 1288.0 z 1495.0
! @output reach x 1999.9 z 445.0
! @output far ERR_ROBLIMIT
! @output edge 180.0
! @output beyond 1 ERR_ROBLIMIT
! @output beyond 3 ERR_ROBLIMIT
! @output t 0.257
  CONST jointtarget calib := [[0,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget stretched := [[0,90,-80.914488,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget edge := [[180,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget past1 := [[181,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget past3 := [[0,0,-181,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget turned := [[45,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget far := [[2249.9179,0,445],[0.707107,0,0.707107,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS tooldata wc := [TRUE,[[0,0,-200],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];
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
