MODULE collision_recovery
! @format 3
! @section 7.6
! @expect ok
! @statement-time 0
! @io io/collision.io
! @description The example of section 7.6: a collision (at 2.5 s, the stimulus's "at 2.5 collision") during MoveJ p20 stops the robot and raises ERR_COLL_STOP in main, whose handler moves away on a new path level (StorePath, MoveJ p30, RestoPath), restarts the stopped path (StartMove) and RETRYs; the interrupted MoveJ is not planned again (R-7.6-a), the robot finishes it from where it stood.
! @output ERR_COLL_STOP at 2500
! @output at p20 TRUE
  CONST robtarget p10 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p20 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p30 := [[300,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  PROC main()
    VAR pos here;
    ClkStart clk;
    MoveJ p10, v200, fine, tool0;
    MoveJ p20, v200, fine, tool0;
    here := CPos(\Tool:=tool0);
    TPWrite "at p20 " \Bool:=(Distance(here, p20.trans) < 0.01);
  ERROR
    TEST ERRNO
    CASE ERR_COLL_STOP:
      TPWrite "ERR_COLL_STOP at " \Num:=Round(1000 * ClkRead(clk));
      StorePath;
      MoveJ p30, v200, fine, tool0;
      RestoPath;
      StartMove;
    ENDTEST
    RETRY;
  ENDPROC
ENDMODULE
