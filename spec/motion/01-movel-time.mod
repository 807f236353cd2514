MODULE movel_time
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @description A 500 mm MoveL at v100 to a fine point takes 500 / 100 = 5 s (doc/motion.md, T-cartesian); the program pointer leaves a stop point when the robot stands in it (PP-fine), so ClkRead after the move reads 5, and CRobT then reads the programmed point with its confdata.
! @output t 5
! @output at 300.0 250.0 300.0
! @output conf 0 0 0
! @output 0 0 1 0
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  PROC main()
    VAR robtarget here;
    MoveJ p1, v1000, fine, tool0;
    ClkStart clk;
    MoveL p2, v100, fine, tool0;
    TPWrite "t " \Num:=ClkRead(clk);
    here := CRobT(\Tool:=tool0 \WObj:=wobj0);
    TPWrite "at " + NumToStr(here.trans.x, 1) + " " + NumToStr(here.trans.y, 1) + " " + NumToStr(here.trans.z, 1);
    TPWrite "conf " + NumToStr(here.robconf.cf1, 0) + " " + NumToStr(here.robconf.cf4, 0) + " " + NumToStr(here.robconf.cf6, 0);
    TPWrite NumToStr(Round(here.rot.q1 \Dec:=3), 0) + " " + NumToStr(Round(here.rot.q2 \Dec:=3), 0) + " " + NumToStr(Round(here.rot.q3 \Dec:=3), 0) + " " + NumToStr(Round(here.rot.q4 \Dec:=3), 0);
  ENDPROC
ENDMODULE
