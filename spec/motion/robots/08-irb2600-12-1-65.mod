MODULE r_irb2600_12_1_65
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @robot irb2600-12-1.65
! @description The ABB IRB 2600-12/1.65 of the robot library (doc/motion.md "The robot library", robots/irb2600-12-1.65.robot), by its library name. A known pose: at the calibration position (all axes 0) the flange is at [a1 + d4 + d6, 0, d1 + a2 + a3] = [1030, 0, 1260] (the product specification's dimensions). Reach: with axis 2 at 90 and axis 3 at -81.769 the arm is stretched forward, the wrist centre (tool wc: tool0 moved back along its z by d6 = 85) at x = 1653.2745, z = 445 (a1 + (a2 + sqrt(a3^2 + d4^2)) sin(axis 2)): the published reach 1650 mm within 2.5 %; a point 50 mm beyond the flange stretched level is out of reach (ERR_ROBLIMIT). Joint limits: axis 1 at its limit 180 moves, one degree beyond is refused (ERR_ROBLIMIT), axis 2 at 150 moves, as axis 2 one degree beyond 155 or below -95 and axis 3 one degree below -180 (the product specification's ranges: axis 2 +155 to -95, axis 3 +75 to -180). A move timed: axis 1 turning 45 degrees at its 175 degrees/s takes 45 / 175 = 0.257 s (T-joint: more than the flange's chord at v5000 and the reorientation at v_ori).
! @output home x 1030.0 z 1260.0
! @output reach x 1653.3 z 445.0
! @output far ERR_ROBLIMIT
! @output edge 180.0
! @output beyond 1 ERR_ROBLIMIT
! @output forward 150.0
! @output beyond 2 ERR_ROBLIMIT
! @output back 2 ERR_ROBLIMIT
! @output beyond 3 ERR_ROBLIMIT
! @output t 0.257
  CONST jointtarget calib := [[0,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget stretched := [[0,90,-81.769025,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget edge := [[180,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget past1 := [[181,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget forward := [[0,150,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget back2 := [[0,-96,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget past2 := [[0,156,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget past3 := [[0,0,-181,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget turned := [[45,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget far := [[1788.2745,0,445],[0.707107,0,0.707107,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS tooldata wc := [TRUE,[[0,0,-85],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];
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
    MoveAbsJ forward, v1000, fine, tool0;
    j := CJointT();
    TPWrite "forward " + NumToStr(j.robax.rax_2, 1);
    what := "beyond 2";
    MoveAbsJ past2, v1000, fine, tool0;
    what := "back 2";
    MoveAbsJ back2, v1000, fine, tool0;
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
