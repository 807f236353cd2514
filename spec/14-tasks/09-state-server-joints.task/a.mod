MODULE state_a
! @format 4
! @task T_ROB1
! @section 14
! @expect ok
! @statement-time 0
! @description A task without a robot reads the motion task's robot as it moves (R-14-pos1), as a ROS-Industrial style state server reports the joints: T_ROB1 turns axis 6 by 210 degrees in 0.5 s (T-joint: 420 degrees/s, the axes linear in time); ROS_STATE's CJointT() every 0.1 s reads 42, 84, 126, 168, 210. \TaskName naming the motion task, or the task itself, reads the same robot; CRobT and CPos give its TCP (tool0 at the flange, which axis 6 does not move: [374,0,630], K-home). A motion task naming a task without a robot: ERR_NOT_MOVETASK; a name that is no task, or a taskid that identifies none: ERR_TASKNAME.
! @output B: t 100 axis 6 42
! @output B: t 200 axis 6 84
! @output B: t 300 axis 6 126
! @output B: t 400 axis 6 168
! @output B: t 500 axis 6 210
! @output A: ROS_STATE has no robot
! @output B: T_ROB1's axis 6 210
! @output B: its own name's axis 6 210
! @output B: CRobT 374 0 630
! @output B: CPos 374 0 630
! @output B: ERR_TASKNAME
! @output B: ERR_TASKNAME
  CONST jointtarget turned := [[0, 0, 0, 0, 0, 210], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    VAR jointtarget j;
    MoveAbsJ turned, v1000, fine, tool0;
    WaitTime 0.05;
    j := CJointT(\TaskName:="ROS_STATE");
    TPWrite "A: not reached";
  ERROR
    IF ERRNO = ERR_NOT_MOVETASK TPWrite "A: ROS_STATE has no robot";
    RETURN;
  ENDPROC
ENDMODULE
