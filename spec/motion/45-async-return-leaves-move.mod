MODULE return_leaves_move
! @format 3
! @section 7.6
! @expect ok
! @statement-time 0
! @io io/collision.io
! @description A collision (2.5 s) while the program pointer waits in proc1's MoveJ p20: proc1's handler takes it (section 7.6, step 1) and ends with RETURN after StartMove. RETURN leaves the move instruction in progress, so its path is deleted as for any move instruction an error leaves (R-7.6-b, R-7.4-m): the robot stands where it collided and never reaches p20.
! @output proc1 ERR_COLL_STOP
! @output at p20 FALSE
! @output still TRUE
  CONST robtarget p10 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p20 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR pos here;
    VAR pos later;
    proc1;
    here := CPos(\Tool:=tool0);
    TPWrite "at p20 " \Bool:=(Distance(here, p20.trans) < 0.01);
    WaitTime 3;
    later := CPos(\Tool:=tool0);
    TPWrite "still " \Bool:=(Distance(here, later) < 0.01);
  ENDPROC
  PROC proc1()
    MoveJ p10, v200, fine, tool0;
    MoveJ p20, v200, fine, tool0;
  ERROR
    IF ERRNO = ERR_COLL_STOP THEN
      TPWrite "proc1 ERR_COLL_STOP";
      StartMove;
      RETURN;
    ENDIF
  ENDPROC
ENDMODULE
