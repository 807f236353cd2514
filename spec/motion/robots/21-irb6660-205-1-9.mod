MODULE r_irb6660_205_1_9
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @robot ROB1_6660_1.90_205
! @description The ABB IRB 6660-205/1.9 of the robot library (doc/motion.md "The robot library", robots/irb6660-205-1.9.robot), by its MOC.cfg robot type ROB1_6660_1.90_205 (a controller backup's). A known pose: at the calibration position (all axes 0) the flange is at [a1 + d4 + d6, 0, d1 + a2 + a3] = [1393.0, 0, 1794.5] (the product specification's dimensions). Reach: with axis 2 at 85 and axis 3 at 12.4088 (axis 3 against the horizontal, axis 2 plus the chain's joint 3 atan2(a3, d4) - 90) the arm is stretched forward (structure coupled-axis3: axis 3 is the upper arm's attitude against the horizontal), the wrist centre (tool wc: tool0 moved back along its z by d6 = 200) at x = a1 + (a2 + sqrt(a3^2 + d4^2)) sin(axis 2) = 1929.6431, z = d1 + (a2 + sqrt(a3^2 + d4^2)) cos(axis 2) = 957.0753: the published reach 1900 mm within 2.5 %; a point 50 mm beyond the flange stretched level is out of reach (ERR_ROBLIMIT). Joint limits: axis 1 at its limit 180 moves, one degree beyond is refused (ERR_ROBLIMIT), as axis 3 one degree below -20. A move timed: axis 1 turning 45 degrees at its 130 degrees/s takes 45 / 130 = 0.346 s.
! @output home x 1393.0 z 1794.5
! @output reach x 1929.6 z 957.1
! @output far ERR_ROBLIMIT
! @output edge 180.0
! @output beyond 1 ERR_ROBLIMIT
! @output beyond 3 ERR_ROBLIMIT
! @output t 0.346
  CONST jointtarget calib := [[0,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget stretched := [[0,85,12.408808,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget edge := [[180,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget past1 := [[181,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget past3 := [[0,0,-21,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget turned := [[45,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget far := [[2185.8680,0,814.5],[0.707107,0,0.707107,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
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
