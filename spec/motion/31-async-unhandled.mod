MODULE async_unhandled
! @format 3
! @section 7.6
! @section 7.4
! @expect ok
! @statement-time 0
! @io io/collision-3s.io
! @description Section 7.6, step 5: "if there is no error handler at all, RAPID stops execution when the error occurs". The collision at 3 s (the robot on its way to p20, the program pointer in the WaitTime of wait_here) finds no handler in the motion pointer's routine, main, nor up from the program pointer's, wait_here: the system error handler stops the task with ERR_COLL_STOP at the WaitTime, at once: wait_here's UNDO handler does not run (R-7.4-m) and nothing after the WaitTime runs.
! @output before
! @exit 1
! @error ERR_COLL_STOP 22:5
  CONST robtarget p10 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p20 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    MoveJ p10, v1000, fine, tool0;
    MoveJ \Conc, p20, v10, fine, tool0;
    wait_here;
    TPWrite "after";
  ENDPROC
  PROC wait_here()
    TPWrite "before";
    WaitTime 10;
    TPWrite "not reached";
  UNDO
    TPWrite "wait_here abandoned";
  ENDPROC
ENDMODULE
