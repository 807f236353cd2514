MODULE backward_track
! @format 3
! @section 6.3
! @expect ok
! @robot robot/track.robot
! @description Backward moves on a track (section 6.3, R-6.3-m, doc/motion.md X-target, X-track): forward, MoveL p1 and MoveL p2 take the TCP along x with the track (eax_a 200, then 500); backward, the BACKWARD handler's moves retrace them newest first with the external axes too: MoveL p2 takes the robot from p2 back to p1 (track 200), MoveL p1 from p1 back to where it stood before the forward MoveL p1, the arm's home pointing down at x 302 with the track at 0. The backward run is pinned by test/golden/debug-back-track.cmd.
! @exit 0
! @output at x 802 track 500
  CONST jointtarget home := [[0,0,0,0,90,0],[0,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p1 := [[502,0,558],[0,0,1,0],[0,0,0,0],[200,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[802,0,558],[0,0,1,0],[0,0,0,0],[500,9E9,9E9,9E9,9E9,9E9]];
  VAR pos here;
  VAR jointtarget j;
  PROC MoveTo()
    MoveL p1, v1000, fine, tool0;
    MoveL p2, v500, fine, tool0;
  BACKWARD
    MoveL p2, v500, fine, tool0;
    MoveL p1, v1000, fine, tool0;
    here := CPos(\Tool:=tool0);
    j := CJointT();
    TPWrite "back at x " + NumToStr(here.x, 0) + " track " + NumToStr(j.extax.eax_a, 0);
  ENDPROC
  PROC main()
    MoveAbsJ home, v1000, fine, tool0;
    MoveTo;
    here := CPos(\Tool:=tool0);
    j := CJointT();
    TPWrite "at x " + NumToStr(here.x, 0) + " track " + NumToStr(j.extax.eax_a, 0);
  ENDPROC
ENDMODULE
