MODULE r_irb760_450_3_2
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @robot ROB3_760_3.2_450
! @description The ABB IRB 760-450/3.18 of the robot library (robots/irb760-450-3.2.robot), by the MOC.cfg robot type of a controller backup's third robot, ROB3_760_3.2_450: a palletiser (structure palletiser, doc/motion.md R-structure; doc/rulings.md R-structure). A known pose: at the calibration position the lower arm stands up, the upper arm is level and the flange hangs 290 ahead of and 269 below its end: [300 + 1350 + 290, 0, 814.5 + 1280 - 269] = [1940, 0, 1825.5], tool0 pointing down. Reach: axis 2 at its limit 82 with axis 3 level puts the flange at x = 300 + 1280 sin 82 + 1350 + 290 = 3207.5, z = 814.5 + 1280 cos 82 - 269 = 723.6 (the published reach 3.18 m); 100 mm further is out of reach, and so is a flange tilted 10 degrees (it hangs level). A MoveL keeps the flange level. Joint limits: axis 2 one degree beyond 82 and axis 3 one below -20 are refused (ERR_ROBLIMIT); axes 4 and 5 are not the arm's, and stand at 0. A move timed: axis 1 turning 45 degrees at its 85 degrees/s (ESTIMATED) takes 0.529 s.
! @output home x 1940.0 z 1825.5 q3 1.0000
! @output reach x 3207.5 z 723.6
! @output far ERR_ROBLIMIT
! @output tilted ERR_ROBLIMIT
! @output line x 1640.0 z 1500.0 q3 1.0000 rax_4 0.0
! @output beyond 2 ERR_ROBLIMIT
! @output beyond 3 ERR_ROBLIMIT
! @output t 0.529
  CONST jointtarget calib := [[0,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget stretched := [[0,82,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget past2 := [[0,83,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget past3 := [[0,0,-21,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget turned := [[45,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget far := [[3307.5,0,723.6],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget tilted := [[1940,0,1825.5],[0,0,0.9961947,-0.0871557],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget low := [[1640,0,1500],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  VAR string what;
  PROC main()
    VAR robtarget r;
    VAR jointtarget j;
    MoveAbsJ calib, v1000, fine, tool0;
    r := CRobT(\Tool:=tool0);
    TPWrite "home x " + NumToStr(r.trans.x, 1) + " z " + NumToStr(r.trans.z, 1) + " q3 " + NumToStr(r.rot.q3, 4);
    MoveAbsJ stretched, v1000, fine, tool0;
    r := CRobT(\Tool:=tool0);
    TPWrite "reach x " + NumToStr(r.trans.x, 1) + " z " + NumToStr(r.trans.z, 1);
    what := "far";
    MoveJ far, v1000, fine, tool0;
    what := "tilted";
    MoveJ tilted, v1000, fine, tool0;
    MoveAbsJ calib, v1000, fine, tool0;
    MoveL low, v1000, fine, tool0;
    r := CRobT(\Tool:=tool0);
    j := CJointT();
    TPWrite "line x " + NumToStr(r.trans.x, 1) + " z " + NumToStr(r.trans.z, 1) + " q3 " + NumToStr(r.rot.q3, 4) + " rax_4 " + NumToStr(j.robax.rax_4, 1);
    what := "beyond 2";
    MoveAbsJ past2, v1000, fine, tool0;
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
