MODULE predefined_taskid_a
! @format 4
! @task T_ROB1
! @section 14
! @expect ok
! @description Every program task has a predefined taskid variable, its name followed by Id (ABB's taskid page; doc/rulings.md R-14-taskid): T_LOG, a task without a robot, reads the robot of T_ROB1 through CJointT's \TaskRef:=T_ROB1Id, and its own (the connected one) through T_LOGId; both are declared in every task of the run.
! @output log: axis 1 of T_ROB1 10
! @output log: my own 10
  PERS bool moved := FALSE;
  PROC main()
    MoveAbsJ [[10,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]], v1000, fine, tool0;
    moved := TRUE;
  ENDPROC
ENDMODULE
