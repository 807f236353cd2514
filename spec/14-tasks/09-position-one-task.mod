MODULE position_one_task
! @format 3
! @section 14
! @expect ok
! @statement-time 0
! @description With one task, T_ROB1 is the motion task: CJointT and CRobT with \TaskName:="T_ROB1" (letter case aside) read its own robot, as without it; a name that is no task of the run raises ERR_TASKNAME (R-14-pos1).
! @output own axis 1 90
! @output own name axis 1 90
! @output CRobT y 374
! @output ERR_TASKNAME
  CONST jointtarget turned := [[90, 0, 0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    VAR jointtarget j;
    VAR robtarget r;
    MoveAbsJ turned, v1000, fine, tool0;
    j := CJointT();
    TPWrite "own axis 1 " \Num:=Round(j.robax.rax_1);
    j := CJointT(\TaskName:="t_rob1");
    TPWrite "own name axis 1 " \Num:=Round(j.robax.rax_1);
    r := CRobT(\TaskName:="T_ROB1" \Tool:=tool0);
    TPWrite "CRobT y " \Num:=Round(r.trans.y);
    j := CJointT(\TaskName:="T_ROB2");
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_TASKNAME TPWrite "ERR_TASKNAME";
    RETURN;
  ENDPROC
ENDMODULE
