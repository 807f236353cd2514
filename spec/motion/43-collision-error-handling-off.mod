MODULE collision_handling_off
! @format 3
! @section 7.6
! @expect ok
! @statement-time 0
! @io io/collision.io
! @description Section 7.6: RAPID execution need not stop at a collision only when the system parameter Collision Error Handling is set. The program switches it off (WriteCfgData ... 0, as example 4 does after its moves): the collision at 2.5 s during MoveJ p20 stops the robot and the task at once with ERR_COLL_STOP at the MoveJ (the system error handler); main's error handler and its UNDO handler do not run (R-7.6-m).
! @output before
! @exit 1
! @error ERR_COLL_STOP 17:5
  CONST robtarget p10 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p20 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    WriteCfgData "/SYS/SYS_MISC/CollisionErrorHandling", "Value", 0;
    MoveJ p10, v200, fine, tool0;
    TPWrite "before";
    MoveJ p20, v200, fine, tool0;
    TPWrite "after";
  ERROR
    TPWrite "handler";
    RETRY;
  UNDO
    TPWrite "undo";
  ENDPROC
ENDMODULE
