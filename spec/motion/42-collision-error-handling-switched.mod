MODULE collision_handling_switched
! @format 3
! @section 7.6
! @expect ok
! @statement-time 0
! @io io/collision.io
! @description Example 4 of section 7.6 (its WriteCfqData read as WriteCfgData): the program switches the system parameter Collision Error Handling on around its moves and off again, also in its UNDO handler. The collision at 2.5 s during MoveJ p20 is handled as in example 1 of the section's start (spec/motion/22): ERR_COLL_STOP in main, StorePath, MoveJ p30, RestoPath, StartMove, RETRY; the robot finishes the move to p20.
! @output ERR_COLL_STOP at 2500
! @output at p20 TRUE
  CONST robtarget p10 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p20 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p30 := [[300,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  PROC main()
    VAR pos here;
    ClkStart clk;
    WriteCfgData "/SYS/SYS_MISC/CollisionErrorHandling", "Value", 1;
    MoveJ p10, v200, fine, tool0;
    MoveJ p20, v200, fine, tool0;
    WriteCfgData "/SYS/SYS_MISC/CollisionErrorHandling", "Value", 0;
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
  UNDO
    WriteCfgData "/SYS/SYS_MISC/CollisionErrorHandling", "Value", 0;
  ENDPROC
ENDMODULE
