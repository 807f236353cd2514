MODULE named_motion_a
! @format 4
! @task T_ROB1
! @section 14
! @section 7
! @motion-task T_MOVE
! @expect ok
! @description The motion task need not be the first (@motion-task, rapid-sem run --motion-task): T_ROB1 is then a task without a robot, its MoveJ raises ERR_NOT_MOVETASK, which its error handler handles; GetTaskName \MecTaskNo names the motion task, which moves (its move takes virtual time, so its output comes last).
! @output ERR_NOT_MOVETASK
! @output motion task T_MOVE 2
! @output T_MOVE moved
  CONST jointtarget home := [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    VAR num k;
    MoveAbsJ home, v100, fine, tool0;
    TPWrite "motion task " + GetTaskName(\MecTaskNo := k) + " " + NumToStr(k, 0);
  ERROR
    IF ERRNO = ERR_NOT_MOVETASK THEN
      TPWrite "ERR_NOT_MOVETASK";
      TRYNEXT;
    ENDIF
  ENDPROC
ENDMODULE
