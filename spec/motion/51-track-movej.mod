MODULE track_movej
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @robot robot/track.robot
! @description MoveJ on a track (doc/motion.md T-joint, X-time, X-track): from the arm's home pointing down at [302,0,558] with the track at 0, MoveJ to [802,100,558] with the track at 500. In the base, now 500 mm along x, the target is [302,100,558]: axis 1 turns atan(100 / 302) = 18.3 degrees (0.07 s at 250 deg/s), the other axes less; the track's 500 mm take 0.5 s at 1000 mm/s; the TCP's chord in the world, sqrt(500^2 + 100^2) = 509.9 mm, takes 1.0198 s at v500, the longest: T = 1.020 s.
! @output t 1.020 x 802.0 y 100.0 z 558.0 eax_a 500.0 rax_1 18.3
  CONST jointtarget home := [[0,0,0,0,90,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p := [[802,100,558],[0,0,1,0],[0,0,0,0],[500,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  PROC main()
    VAR jointtarget j;
    VAR pos c;
    MoveAbsJ home, v1000, fine, tool0;
    ClkStart clk;
    MoveJ p, v500, fine, tool0;
    j := CJointT();
    c := CPos(\Tool:=tool0);
    TPWrite "t " + NumToStr(ClkRead(clk), 3) + " x " + NumToStr(c.x, 1) + " y " + NumToStr(c.y, 1) + " z " + NumToStr(c.z, 1) + " eax_a " + NumToStr(j.extax.eax_a, 1) + " rax_1 " + NumToStr(j.robax.rax_1, 1);
  ENDPROC
ENDMODULE
