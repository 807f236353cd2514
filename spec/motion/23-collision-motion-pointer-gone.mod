MODULE MainModule
! @format 3
! @section 7.6
! @expect ok
! @statement-time 0
! @io io/collision-3s.io
! @description Example 2 of section 7.6 (with one \Conc move: under PP-conc a second one would hold the program pointer until the first one's motion ends): Routine2 hands a \Conc move to the robot and returns; the program pointer waits in Routine1's WaitTime 10 when the robot collides on its way to p20 (3 s). The motion pointer's routine is no longer in the call chain, so the error handler of the program pointer's routine, Routine1, runs (section 7.6, step 3); it ends without recovering, and the system error handler stops the task with ERR_COLL_STOP at the WaitTime.
! @output Routine1
! @exit 1
! @error ERR_COLL_STOP 19:5
  CONST robtarget p10 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p20 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    MoveJ p10, v1000, z50, tool0;
    Routine1;
  ENDPROC
  PROC Routine1()
    Routine2;
    WaitTime 10;
  ERROR
    TPWrite "Routine1";
  ENDPROC
  PROC Routine2()
    MoveJ \Conc, p20, v10, z50, tool0;
  ERROR
    TPWrite "Routine2";
  ENDPROC
ENDMODULE
