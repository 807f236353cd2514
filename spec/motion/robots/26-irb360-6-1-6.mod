MODULE r_irb360_6_1600
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @robot ROB1_360_1.6_6
! @description The ABB IRB 360-6/1600 of the robot library (robots/irb360-6-1.6.robot), by the MOC.cfg robot type of a controller backup: a delta (structure delta, doc/motion.md R-structure; its dimensions ESTIMATED, doc/rulings.md R-structure-delta). A known pose: at the calibration position the three arms are level and the plate hangs on the base's axis at the depth the rods leave, sqrt(1200^2 - (150 + 450)^2) = 1039.2, the flange 50 below: [0, 0, -1089.2], pointing down. Reach: a point 800 mm out (the working range's radius) is reached with the flange level; 1200 mm out is out of reach, and so is a flange tilted 10 degrees. Axis 4 turns the flange about its z: at 90 tool0's x axis is along the base's y. Joint limits: axis 1 one degree beyond 110 is refused (ERR_ROBLIMIT). A move timed: axis 1 turning 60 degrees takes 60 / 600 = 0.100 s at its 600 degrees/s, but moves the flange 642.5 mm (to [-642.4, 0, -1076.0]), 0.129 s at v5000: the longer rules (T-joint).
! @output home x 0.0 y 0.0 z -1089.2 q3 1.0000
! @output reach x 800.0 z -1020.0
! @output far ERR_ROBLIMIT
! @output tilted ERR_ROBLIMIT
! @output turned q2 0.7071 q3 0.7071 rax_4 90.0
! @output beyond 1 ERR_ROBLIMIT
! @output t 0.129
  CONST jointtarget calib := [[0,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget turn4 := [[0,0,0,90,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget past1 := [[111,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget arm1 := [[60,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget edge := [[800,0,-1020],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget far := [[1200,0,-1020],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget tilted := [[0,0,-1089.2],[0,0,0.9961947,-0.0871557],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  VAR string what;
  PROC main()
    VAR robtarget r;
    VAR jointtarget j;
    MoveAbsJ calib, v1000, fine, tool0;
    r := CRobT(\Tool:=tool0);
    TPWrite "home x " + NumToStr(r.trans.x, 1) + " y " + NumToStr(r.trans.y, 1) + " z " + NumToStr(r.trans.z, 1) + " q3 " + NumToStr(r.rot.q3, 4);
    MoveL edge, v1000, fine, tool0;
    r := CRobT(\Tool:=tool0);
    TPWrite "reach x " + NumToStr(r.trans.x, 1) + " z " + NumToStr(r.trans.z, 1);
    what := "far";
    MoveL far, v1000, fine, tool0;
    what := "tilted";
    MoveJ tilted, v1000, fine, tool0;
    MoveAbsJ turn4, v1000, fine, tool0;
    r := CRobT(\Tool:=tool0);
    j := CJointT();
    TPWrite "turned q2 " + NumToStr(Abs(r.rot.q2), 4) + " q3 " + NumToStr(Abs(r.rot.q3), 4) + " rax_4 " + NumToStr(j.robax.rax_4, 1);
    what := "beyond 1";
    MoveAbsJ past1, v1000, fine, tool0;
    MoveAbsJ calib, v1000, fine, tool0;
    ClkStart clk;
    MoveAbsJ arm1, v5000, fine, tool0;
    TPWrite "t " + NumToStr(ClkRead(clk), 3);
  ERROR
    IF ERRNO = ERR_ROBLIMIT THEN
      TPWrite what + " ERR_ROBLIMIT";
      TRYNEXT;
    ENDIF
  ENDPROC
ENDMODULE
