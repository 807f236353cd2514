MODULE moveextj_zone
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @robot robot/track.robot
! @description MoveExtJ through a fly-by point (doc/motion.md X-zone, Z-clip, Z-corner, PP-flyby): e1 moves eax_a 0 to 1000 (1 s at the track's 1000 mm/s), z10; e2 moves eax_b 0 to 90 (1 s at the positioner's 90 deg/s), fine. Nothing else moves, so the corner's shares are the external axes' zones against their travel: z10's zone_leax 15 / 1000 = 0.015 of e1 and its zone_reax 1.5 / 90 of e2. The program pointer leaves e1 the look-ahead 0.1 s before its zone, at 1 - 0.015 - 0.1 = 0.885 s; the corner, a quadratic Bezier in axis space from (985, 0) through (1000, 0) to (1000, 1.5), runs from 0.985 s to 1 + 1/60 s, so at 1 s (u = 0.015 / (0.015 + 1/60) = 9/19) eax_a is 1000 - 15 (10/19)^2 = 995.8 and eax_b 1.5 (9/19)^2 = 0.3; zones change no time: the robot stands at e2 at 2 s.
! @output left e1 0.885
! @output at 1 s eax_a 995.8 eax_b 0.3
! @output stands 2.000 eax_a 1000.0 eax_b 90.0
  CONST jointtarget home := [[0,0,0,0,90,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget e1 := [[0,0,0,0,0,0],[1000,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget e2 := [[0,0,0,0,0,0],[9E9,90,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  VAR intnum tick;
  TRAP sample
    VAR jointtarget j;
    j := CJointT();
    TPWrite "at 1 s eax_a " + NumToStr(j.extax.eax_a, 1) + " eax_b " + NumToStr(j.extax.eax_b, 1);
  ENDTRAP
  PROC main()
    VAR jointtarget j;
    MoveAbsJ home, v1000, fine, tool0;
    ClkStart clk;
    CONNECT tick WITH sample;
    ITimer \Single, 1, tick;
    MoveExtJ e1, v1000, z10;
    TPWrite "left e1 " + NumToStr(ClkRead(clk), 3);
    MoveExtJ e2, v1000, fine;
    j := CJointT();
    TPWrite "stands " + NumToStr(ClkRead(clk), 3) + " eax_a " + NumToStr(j.extax.eax_a, 1) + " eax_b " + NumToStr(j.extax.eax_b, 1);
  ENDPROC
ENDMODULE
