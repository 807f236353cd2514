MODULE r_irb1200_7_0_7
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @robot irb1200-7-0.7
! @description The ABB IRB 1200-7/0.7 of the robot library (doc/motion.md "The robot library", robots/irb1200-7-0.7.robot), by its library name. A known pose: at the calibration position (all axes 0) the flange is at [a1 + d4 + d6, 0, d1 + a2 + a3] = [433, 0, 791.1] (the product specification's dimensions). Reach: with axis 2 at 90 and axis 3 at -83.1765 the arm is stretched forward, the wrist centre (tool wc: tool0 moved back along its z by d6 = 82) at x = 703.5039, z = 399.1 (a1 + (a2 + sqrt(a3^2 + d4^2)) sin(axis 2)): the published reach 703 mm within 2.5 %; a point 50 mm beyond the flange stretched level is out of reach (ERR_ROBLIMIT). Joint limits: axis 1 at its limit 170 moves, one degree beyond is refused (ERR_ROBLIMIT), as axis 3 one degree below -200. A move timed: axis 1 turning 45 degrees at its 288 degrees/s takes 45 / 288 = 0.156 s (T-joint: more than the flange's chord at v5000 and the reorientation at v_ori).
! @output home x 433.0 z 791.1
! @output reach x 703.5 z 399.1
! @output far ERR_ROBLIMIT
! @output edge 170.0
! @output beyond 1 ERR_ROBLIMIT
! @output beyond 3 ERR_ROBLIMIT
! @output t 0.156
  CONST jointtarget calib := [[0,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget stretched := [[0,90,-83.176538,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget edge := [[170,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget past1 := [[171,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget past3 := [[0,0,-201,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget turned := [[45,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget far := [[835.5039,0,399.1],[0.707107,0,0.707107,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS tooldata wc := [TRUE,[[0,0,-82],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];
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
