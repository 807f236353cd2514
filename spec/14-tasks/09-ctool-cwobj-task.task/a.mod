MODULE tool_a
! @format 4
! @task T_ROB1
! @section 14
! @expect ok
! @statement-time 0
! @description CTool and CWObj read the active tool and work object of the task whose robot CJointT reads (ABB's CTool and CWObj pages: \TaskRef or \TaskName names the task; R-14-pos2, as R-14-pos1 for CJointT): T_ROB1 moves with the tool gun in the work object table, then says so through a shared persistent; TOOL_B, a task without a robot, reads them without an argument, with \TaskName naming T_ROB1 and with its own name. T_ROB1 naming TOOL_B: ERR_NOT_MOVETASK; a name that is no task, or a taskid that identifies none: ERR_TASKNAME.
! @output A: TOOL_B has no robot
! @output B: tool 0 0 150
! @output B: T_ROB1's tool 0 0 150
! @output B: its own name's tool 0 0 150
! @output B: T_ROB1's wobj 300 0 100
! @output B: its own wobj 300 0 100
! @output B: ERR_TASKNAME
! @output B: ERR_TASKNAME
  PERS tooldata gun := [TRUE, [[0, 0, 150], [1, 0, 0, 0]], [1, [0, 0, 50], [1, 0, 0, 0], 0, 0, 0]];
  PERS wobjdata table := [FALSE, TRUE, "", [[300, 0, 100], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];
  CONST robtarget p := [[0, 0, 200], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PERS bool moved := FALSE;
  PROC main()
    VAR tooldata t;
    MoveJ p, v1000, fine, gun \WObj:=table;
    t := CTool(\TaskName:="TOOL_B");
    TPWrite "A: not reached";
  ERROR
    IF ERRNO = ERR_NOT_MOVETASK TPWrite "A: TOOL_B has no robot";
    moved := TRUE;
    RETURN;
  ENDPROC
ENDMODULE
