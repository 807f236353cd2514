MODULE syncmove_a
! @format 4
! @task T_ROB1
! @section 14
! @expect ok
! @description SyncMoveOn and SyncMoveOff are synchronisation points over the tasks of the list, as WaitSyncTask is (R-14-m); between the two, IsSyncMoveOn is TRUE in both tasks, before and after FALSE. In the motion task SyncMoveOn is a stop point: the move before it has a zone, so the program pointer runs ahead of the robot, but A reaches the synchronisation point only once the robot stands where the move ends (CJointT reads it there); so is SyncMoveOff, after which the robot stands back home. The move in synchronized movement carries \ID, accepted and not a synchronisation point (no other task has a robot). B arrives first at each point and waits; A, arriving last, goes on in its own turn, B in the next.
! @output A before FALSE
! @output B before FALSE
! @output A on TRUE
! @output B on TRUE
! @output A in position TRUE
! @output A off FALSE
! @output B off FALSE
! @output A back TRUE
  VAR syncident sync_on;
  VAR syncident sync_off;
  PERS tasks all_tasks{2} := [["T_ROB1"], ["T_B"]];
  CONST jointtarget home := [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST jointtarget there := [[60, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    VAR jointtarget j;
    TPWrite "A before " \Bool := IsSyncMoveOn();
    MoveAbsJ there, v100, z50, tool0;
    SyncMoveOn sync_on, all_tasks;
    TPWrite "A on " \Bool := IsSyncMoveOn();
    j := CJointT();
    TPWrite "A in position " \Bool := Abs(j.robax.rax_1 - 60) < 0.01;
    MoveAbsJ home \ID := 10, v100, z50, tool0;
    SyncMoveOff sync_off;
    TPWrite "A off " \Bool := IsSyncMoveOn();
    j := CJointT();
    TPWrite "A back " \Bool := Abs(j.robax.rax_1) < 0.01;
  ENDPROC
ENDMODULE
