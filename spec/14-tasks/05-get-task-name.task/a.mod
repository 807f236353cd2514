MODULE name_a
! @format 4
! @task T_ROB1
! @section 14
! @expect ok
! @description GetTaskName: the task's own name; \TaskNo its number (from 1 in the order of the tasks); \MecTaskNo the name and number of the motion task (R-14-d).
! @output T_ROB1 1
! @output T_ARC 2 motion T_ROB1 1
  PROC main()
    VAR num n;
    TPWrite GetTaskName(\TaskNo := n) + " " + NumToStr(n, 0);
  ENDPROC
ENDMODULE
