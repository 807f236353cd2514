MODULE collision_in_chain
! @format 3
! @section 7.6
! @expect ok
! @statement-time 0
! @io io/collision-3s.io
! @description Example 1 of section 7.6: the motion pointer is in proc1 (its \Conc MoveJ to p20 at v10), the program pointer in proc3 (WaitTime 100, called through proc2) when the robot collides at 3 s: the error handler of proc1 runs first (step 1), with the program pointer kept in proc3 (R-7.4-m): proc3 and proc2 are not abandoned. proc1's handler restarts the path and its TRYNEXT executes as RETRY (section 7.4): the program pointer goes on in proc3's WaitTime; proc3 and proc2 return, WaitRob \InPos waits for the robot, which reaches p20.
! @output proc1 TRUE
! @output at p20 TRUE
  CONST robtarget p10 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p20 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR pos here;
    proc1;
    here := CPos(\Tool:=tool0);
    TPWrite "at p20 " \Bool:=(Distance(here, p20.trans) < 0.01);
  ERROR
    TPWrite "main";
  ENDPROC
  PROC proc1()
    MoveJ p10, v1000, fine, tool0;
    MoveJ \Conc, p20, v10, z50, tool0;
    proc2;
    WaitRob \InPos;
  ERROR
    TPWrite "proc1 " \Bool:=(ERRNO = ERR_COLL_STOP);
    StartMove;
    TRYNEXT;
  ENDPROC
  PROC proc2()
    proc3;
  ERROR
    TPWrite "proc2";
  UNDO
    TPWrite "proc2 undo";
  ENDPROC
  PROC proc3()
    WaitTime 100;
  ERROR
    TPWrite "proc3";
  UNDO
    TPWrite "proc3 undo";
  ENDPROC
ENDMODULE
