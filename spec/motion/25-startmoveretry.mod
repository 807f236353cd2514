MODULE startmoveretry_case
! @format 3
! @section 7.6
! @expect ok
! @statement-time 0
! @io io/collision.io
! @description Example 3 of section 7.6: proc1's handler passes the collision on with RAISE; main's handler restarts the path and retries in one instruction, StartMoveRetry (StartMove and RETRY): RAISE left the MoveJ to p20 and deleted its path ("RAISE deletes the last active move instruction", R-7.6-m), so StartMove has nothing to resume; RETRY runs proc1 again and its moves take the robot to p10 and p20. Outside an error handler StartMoveRetry is StartMove (R-7.6-b).
! @output main ERR_COLL_STOP
! @output at p20 TRUE
  CONST robtarget p10 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p20 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    VAR pos here;
    StartMoveRetry;
    proc1;
    here := CPos(\Tool:=tool0);
    TPWrite "at p20 " \Bool:=(Distance(here, p20.trans) < 0.01);
  ERROR
    IF ERRNO = ERR_COLL_STOP THEN
      TPWrite "main ERR_COLL_STOP";
      StartMoveRetry;
    ENDIF
  ENDPROC
  PROC proc1()
    MoveJ p10, v200, fine, tool0;
    MoveJ p20, v200, fine, tool0;
  ERROR
    IF ERRNO = ERR_COLL_STOP THEN
      RAISE;
    ENDIF
  ENDPROC
ENDMODULE
