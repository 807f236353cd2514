MODULE ext_range
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @robot robot/track.robot
! @description An external axis beyond the range of the robot description (eax_a 0 to 2000, eax_b -180 to 180) is a position the robot cannot take: the move raises ERR_ROBLIMIT at its instruction before anything moves (doc/motion.md X-target, M-error), MoveExtJ and MoveL alike; TRYNEXT goes on with the axes where they were. Unhandled, the system error handler stops the task at the move.
! @output ERR_ROBLIMIT 1
! @output ERR_ROBLIMIT 2
! @output still a 0.0 b 0.0 t 0.000
! @exit 1
! @error ERR_ROBLIMIT 39:5
  CONST jointtarget home := [[0,0,0,0,90,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget far := [[0,0,0,0,0,0],[2500,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget below := [[0,0,0,0,0,0],[-1,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget turned := [[302,0,558],[0,0,1,0],[0,0,0,0],[9E9,200,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  VAR num n := 0;
  PROC main()
    VAR jointtarget j;
    MoveAbsJ home, v1000, fine, tool0;
    ClkStart clk;
    tries;
    j := CJointT();
    TPWrite "still a " + NumToStr(j.extax.eax_a, 1) + " b " + NumToStr(j.extax.eax_b, 1) + " t " + NumToStr(ClkRead(clk), 3);
    unhandled;
  ENDPROC
  PROC tries()
    MoveExtJ far, v1000, fine;
    MoveL turned, v1000, fine, tool0;
  ERROR
    IF ERRNO = ERR_ROBLIMIT THEN
      n := n + 1;
      TPWrite "ERR_ROBLIMIT " + NumToStr(n, 0);
    ENDIF
    TRYNEXT;
  ENDPROC
  PROC unhandled()
    MoveExtJ below, v1000, fine;
  ENDPROC
ENDMODULE
