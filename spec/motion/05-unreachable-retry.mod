MODULE unreachable_retry
! @format 3
! @section 7.5
! @expect ok
! @statement-time 0
! @description A target outside the robot's reach raises ERR_ROBLIMIT at the move (doc/rulings.md R-4.1-e); the routine's error handler corrects the target and RETRY executes the move again, which now reaches it.
! @output ERR_ROBLIMIT
! @output at 300.0 250.0 300.0
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR pos p;
    VAR robtarget target := [[2000,0,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    MoveJ p1, v1000, fine, tool0;
    MoveL target, v100, fine, tool0;
    p := CPos(\Tool:=tool0);
    TPWrite "at " + NumToStr(p.x, 1) + " " + NumToStr(p.y, 1) + " " + NumToStr(p.z, 1);
  ERROR
    IF ERRNO = ERR_ROBLIMIT THEN
      TPWrite "ERR_ROBLIMIT";
      target := p2;
      RETRY;
    ENDIF
  ENDPROC
ENDMODULE
