MODULE r_irb7600_400_2_55
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @robot ROB1_7600_2.55_400
! @description The ABB IRB 7600-400/2.55 of the robot library (doc/motion.md "The robot library", robots/irb7600-400-2.55.robot), by its MOC.cfg robot type ROB1_7600_2.55_400 (a controller backup's). A known pose: at the calibration position (all axes 0) the flange is at [a1 + d4 + d6, 0, d1 + a2 + a3] = [1716.0, 0, 2020.0] (the product specification's dimensions). Reach: with axis 2 at 85 and axis 3 at 3.8807 (axis 3 against the horizontal, axis 2 plus the chain's joint 3 atan2(a3, d4) - 90) the arm is stretched forward (structure coupled-axis3: axis 3 is the upper arm's attitude against the horizontal), the wrist centre (tool wc: tool0 moved back along its z by d6 = 250) at x = a1 + (a2 + sqrt(a3^2 + d4^2)) sin(axis 2) = 2545.6550, z = d1 + (a2 + sqrt(a3^2 + d4^2)) cos(axis 2) = 966.8456: the published reach 2550 mm within 2.5 %; a point 50 mm beyond the flange stretched level is out of reach (ERR_ROBLIMIT). Joint limits: axis 1 at its limit 180 moves, one degree beyond is refused (ERR_ROBLIMIT), as axis 3 one degree below -180. A move timed: axis 1 turning 45 degrees at its 75 degrees/s takes 45 / 75 = 0.600 s.
! @output home x 1716.0 z 2020.0
! @output reach x 2545.7 z 966.8
! @output far ERR_ROBLIMIT
! @output edge 180.0
! @output beyond 1 ERR_ROBLIMIT
! @output beyond 3 ERR_ROBLIMIT
! @output t 0.600
  CONST jointtarget calib := [[0,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget stretched := [[0,85,3.880659,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget edge := [[180,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget past1 := [[181,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget past3 := [[0,0,-181,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget turned := [[45,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget far := [[2853.8129,0,780],[0.707107,0,0.707107,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS tooldata wc := [TRUE,[[0,0,-250],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];
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
