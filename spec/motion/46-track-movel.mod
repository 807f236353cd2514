MODULE track_movel
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @robot robot/track.robot
! @description A robot on a track (eax_a, linear, carries the base along world x at up to 1000 mm/s; doc/motion.md X-desc, X-track): robtargets are in the world and the track is an integrated axis (R-4.1-x). MoveL p2 moves the TCP 500 mm at v100 (5 s) while the track moves 0 to 500 (0.5 s at min(v_leax 5000, 1000)): T = max(5, 0.5) = 5 s (X-time), and both go at one pace, so at 2.5 s the TCP is at x 302 + 250 and the track at 250 (X-interp). Then p3, the same point with the track at 700: the TCP stays, the base moves 200 mm in 200 / 1000 = 0.2 s, and halfway the TCP is still at x 802 with the track at 600; CJointT and CRobT report the external axes.
! @output half x 552.0 z 558.0 eax_a 250.0
! @output t 5.000 x 802.0 eax_a 500.0 eax_b 0.0 rax_5 90.0
! @output half x 802.0 eax_a 600.0
! @output t 0.200 x 802.0 eax_a 700.0 robt 700.0
  CONST jointtarget home := [[0,0,0,0,90,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[802,0,558],[0,0,1,0],[0,0,0,0],[500,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p3 := [[802,0,558],[0,0,1,0],[0,0,0,0],[700,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  PROC main()
    VAR jointtarget j;
    VAR robtarget r;
    VAR pos p;
    MoveAbsJ home, v1000, fine, tool0;
    ConfL \Off;
    ClkStart clk;
    MoveL \Conc, p2, v100, fine, tool0;
    WaitTime 2.5;
    p := CPos(\Tool:=tool0);
    j := CJointT();
    TPWrite "half x " + NumToStr(p.x, 1) + " z " + NumToStr(p.z, 1) + " eax_a " + NumToStr(j.extax.eax_a, 1);
    WaitRob \InPos;
    j := CJointT();
    p := CPos(\Tool:=tool0);
    TPWrite "t " + NumToStr(ClkRead(clk), 3) + " x " + NumToStr(p.x, 1) + " eax_a " + NumToStr(j.extax.eax_a, 1) + " eax_b " + NumToStr(j.extax.eax_b, 1) + " rax_5 " + NumToStr(j.robax.rax_5, 1);
    ClkReset clk;
    ClkStart clk;
    MoveL \Conc, p3, v100, fine, tool0;
    WaitTime 0.1;
    p := CPos(\Tool:=tool0);
    j := CJointT();
    TPWrite "half x " + NumToStr(p.x, 1) + " eax_a " + NumToStr(j.extax.eax_a, 1);
    WaitRob \InPos;
    j := CJointT();
    r := CRobT(\Tool:=tool0);
    TPWrite "t " + NumToStr(ClkRead(clk), 3) + " x " + NumToStr(r.trans.x, 1) + " eax_a " + NumToStr(j.extax.eax_a, 1) + " robt " + NumToStr(r.extax.eax_a, 1);
  ENDPROC
ENDMODULE
