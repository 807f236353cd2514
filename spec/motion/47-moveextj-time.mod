MODULE moveextj_time
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @robot robot/track.robot
! @description MoveExtJ and MoveAbsJ with external axes (doc/motion.md X-time, X-extj, X-target): with speeddata slow (v_leax 200 mm/s, v_reax 45 deg/s), MoveExtJ e1 moves eax_a 0 to 300 (1.5 s) and eax_b 0 to 135 (3 s): 3 s, the longest; the track moved the base 300 mm, so the TCP is at x 302 + 300. Under VelSet 50, e2 moves eax_a 300 to 500 at 100 mm/s: 2 s, eax_b (9E9) keeps 135. e3 gives eax_c, which the robot does not have: ignored, no time, eax_c reads 9E9. \T:=4 gives the whole time. MoveAbsJ back to the arm's home with both axes at 0 at v1000: the track's 300 mm at min(v_leax 5000, 1000) = 0.3 s, the TCP's 300 mm chord at 1000 mm/s = 0.3 s, eax_b's 135 degrees at min(v_reax 1000, 90) = 1.5 s: 1.5 s.
! @output e1 3.000 a 300.0 b 135.0 x 602.0
! @output e2 2.000 a 500.0 b 135.0
! @output e3 0.000 TRUE
! @output T 4.000 a 300.0 b 135.0
! @output abs 1.500 a 0.0 b 0.0 x 302.0
  CONST jointtarget home := [[0,0,0,0,90,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget e1 := [[0,0,0,0,0,0],[300,135,9E9,9E9,9E9,9E9]];
  CONST jointtarget e2 := [[0,0,0,0,0,0],[500,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget e3 := [[0,0,0,0,0,0],[9E9,9E9,100,9E9,9E9,9E9]];
  CONST jointtarget back := [[0,0,0,0,90,0],[0,0,9E9,9E9,9E9,9E9]];
  VAR speeddata slow := [100,500,200,45];
  VAR clock clk;
  PROC main()
    VAR jointtarget j;
    VAR pos p;
    MoveAbsJ home, v1000, fine, tool0;
    ClkStart clk;
    MoveExtJ e1, slow, fine;
    j := CJointT();
    p := CPos(\Tool:=tool0);
    TPWrite "e1 " + NumToStr(ClkRead(clk), 3) + " a " + NumToStr(j.extax.eax_a, 1) + " b " + NumToStr(j.extax.eax_b, 1) + " x " + NumToStr(p.x, 1);
    VelSet 50, 5000;
    ClkReset clk;
    ClkStart clk;
    MoveExtJ e2, slow, fine;
    j := CJointT();
    TPWrite "e2 " + NumToStr(ClkRead(clk), 3) + " a " + NumToStr(j.extax.eax_a, 1) + " b " + NumToStr(j.extax.eax_b, 1);
    VelSet 100, 5000;
    ClkReset clk;
    ClkStart clk;
    MoveExtJ e3, slow, fine;
    j := CJointT();
    TPWrite "e3 " + NumToStr(ClkRead(clk), 3) + " " \Bool:=(j.extax.eax_c = 9E9);
    ClkReset clk;
    ClkStart clk;
    MoveExtJ e1, slow \T:=4, fine;
    j := CJointT();
    TPWrite "T " + NumToStr(ClkRead(clk), 3) + " a " + NumToStr(j.extax.eax_a, 1) + " b " + NumToStr(j.extax.eax_b, 1);
    ClkReset clk;
    ClkStart clk;
    MoveAbsJ back, v1000, fine, tool0;
    j := CJointT();
    p := CPos(\Tool:=tool0);
    TPWrite "abs " + NumToStr(ClkRead(clk), 3) + " a " + NumToStr(j.extax.eax_a, 1) + " b " + NumToStr(j.extax.eax_b, 1) + " x " + NumToStr(p.x, 1);
  ENDPROC
ENDMODULE
