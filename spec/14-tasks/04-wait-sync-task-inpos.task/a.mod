MODULE inpos_a
! @format 4
! @task T_ROB1
! @section 14
! @expect ok
! @description WaitSyncTask \InPos in the motion task: the robot comes to a standstill before the task reaches the meeting point (R-14-f). The move's zone lets the program pointer run ahead of the robot; with \InPos A reaches the meeting point, and reads its position, only once the robot stands where the move ends (without it, CJointT would read the robot still moving).
! @output B goes
! @output A in position TRUE
  VAR syncident meet;
  PERS tasks both{2} := [["T_ROB1"], ["T_B"]];
  CONST jointtarget there := [[90, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    VAR jointtarget j;
    MoveAbsJ there, v100, z50, tool0;
    WaitSyncTask \InPos, meet, both;
    j := CJointT();
    TPWrite "A in position " \Bool := Abs(j.robax.rax_1 - 90) < 0.01;
  ENDPROC
ENDMODULE
