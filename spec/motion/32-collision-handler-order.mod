MODULE handler_order
! @format 3
! @section 7.6
! @expect ok
! @statement-time 0
! @io io/collision-3s.io
! @description Example 1 of section 7.6 with proc1 without an error handler: "the system looks for an error handler first in proc1, then main, proc3 and last proc2". The collision at 3 s (the motion pointer in proc1's \\Conc MoveJ, the program pointer in proc3's WaitTime) is handled by main (step 2), not by proc3 or proc2, which have handlers; main's handler restarts the path and its RETRY goes on where the program pointer is, in proc3 (R-7.4-m): proc3 and proc2 return normally, WaitRob waits for the robot, and main goes on after the call of proc1 with the robot at p20.
! @output main TRUE
! @output proc3 done
! @output at p20 TRUE
  CONST robtarget p10 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p20 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR pos here;
    proc1;
    here := CPos(\Tool:=tool0);
    TPWrite "at p20 " \Bool:=(Distance(here, p20.trans) < 0.01);
  ERROR
    TPWrite "main " \Bool:=(ERRNO = ERR_COLL_STOP);
    StartMove;
    RETRY;
  ENDPROC
  PROC proc1()
    MoveJ p10, v1000, fine, tool0;
    MoveJ \Conc, p20, v10, z50, tool0;
    proc2;
    WaitRob \InPos;
  ENDPROC
  PROC proc2()
    proc3;
  ERROR
    TPWrite "proc2";
  UNDO
    TPWrite "proc2 undo";
  ENDPROC
  PROC proc3()
    WaitTime 5;
    TPWrite "proc3 done";
  ERROR
    TPWrite "proc3";
  UNDO
    TPWrite "proc3 undo";
  ENDPROC
ENDMODULE
