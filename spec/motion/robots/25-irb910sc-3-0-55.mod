MODULE r_irb910sc_3_0_55
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @robot ROB1_910SC_0.55_3
! @description The ABB IRB 910SC-3/0.55 SCARA of the robot library (robots/irb910sc-3-0.55.robot), by its MOC.cfg robot type: structure scara (doc/motion.md "The robot library", doc/rulings.md R-structure-scara). A known pose: at the calibration position the two arms (300 and 250) lie in line along x and the flange is at [550, 0, 200] (the reach), pointing down; axis 1 at 90, axis 2 at -90, axis 3 at -50 mm and axis 4 at 30 put it at [250, 300, 150]. The other elbow: the same target with cfx 0 (axis 2 positive) is reached with axis 1 at atan2(300, 250) - atan2(250, 300) = 10.4, axis 2 at 90 and axis 4 at 10.4 + 90 + 30 = 130.4. A MoveL 100 mm down moves axis 3 alone, to -150 mm (a linear axis). Joint limits: 60 mm above the known pose is 10 mm above axis 3's top (0), refused (ERR_ROBLIMIT), as axis 3 at -181 mm; a flange tilted 10 degrees is out of reach (it points down). A move timed: axis 3 travelling its 180 mm stroke at 1100 mm/s takes 0.164 s.
! @output home x 550.0 y 0.0 z 200.0 q3 1.0000
! @output pose x 250.0 y 300.0 z 150.0
! @output elbow 10.4 90.0 130.4
! @output line -150.0 -90.0 x 250.0 z 50.0
! @output above ERR_ROBLIMIT
! @output beyond 3 ERR_ROBLIMIT
! @output tilted ERR_ROBLIMIT
! @output t 0.164
  CONST jointtarget calib := [[0,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget known := [[90,-90,-50,30,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget past3 := [[0,0,-181,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget bottom := [[0,0,-180,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  VAR string what;
  PROC main()
    VAR robtarget r;
    VAR robtarget k;
    VAR jointtarget j;
    MoveAbsJ calib, v1000, fine, tool0;
    r := CRobT(\Tool:=tool0);
    TPWrite "home x " + NumToStr(r.trans.x, 1) + " y " + NumToStr(r.trans.y, 1) + " z " + NumToStr(r.trans.z, 1) + " q3 " + NumToStr(r.rot.q3, 4);
    MoveAbsJ known, v1000, fine, tool0;
    k := CRobT(\Tool:=tool0);
    TPWrite "pose x " + NumToStr(k.trans.x, 1) + " y " + NumToStr(k.trans.y, 1) + " z " + NumToStr(k.trans.z, 1);
    r := k;
    r.robconf := [0,1,0,0];
    MoveJ r, v1000, fine, tool0;
    j := CJointT();
    TPWrite "elbow " + NumToStr(j.robax.rax_1, 1) + " " + NumToStr(j.robax.rax_2, 1) + " " + NumToStr(j.robax.rax_4, 1);
    MoveAbsJ known, v1000, fine, tool0;
    MoveL Offs(k, 0, 0, -100), v1000, fine, tool0;
    j := CJointT();
    r := CRobT(\Tool:=tool0);
    TPWrite "line " + NumToStr(j.robax.rax_3, 1) + " " + NumToStr(j.robax.rax_2, 1) + " x " + NumToStr(r.trans.x, 1) + " z " + NumToStr(r.trans.z, 1);
    what := "above";
    MoveJ Offs(k, 0, 0, 60), v1000, fine, tool0;
    what := "beyond 3";
    MoveAbsJ past3, v1000, fine, tool0;
    what := "tilted";
    r := k;
    r.rot := OrientZYX(0, 10, 180);
    MoveJ r, v1000, fine, tool0;
    MoveAbsJ calib, v1000, fine, tool0;
    ClkStart clk;
    MoveAbsJ bottom, v5000, fine, tool0;
    TPWrite "t " + NumToStr(ClkRead(clk), 3);
  ERROR
    IF ERRNO = ERR_ROBLIMIT THEN
      TPWrite what + " ERR_ROBLIMIT";
      TRYNEXT;
    ENDIF
  ENDPROC
ENDMODULE
