MODULE back_move_instructions
! @format 3
! @section 6.1
! @expect ok
! @description The move instructions the debugger session test/golden/debug-back-move-instructions.cmd steps backward (section 6.1: a predefined procedure's backward behaviour is its own; R-6.1-move): MoveC back through its circle point, MoveL back on its line (a fly-by point, ending at a stop point backward), MoveJ and MoveAbsJ back to the axis angles they started from; at the first statement of main backward execution refuses. Run forward, the program writes where the robot ends.
! @exit 0
! @output at x 550
  CONST robtarget p1 := [[350,-100,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[350,100,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget pCir := [[450,200,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p3 := [[550,100,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget jStart := [[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR pos here;
  PROC main()
    MoveAbsJ jStart, v1000, fine, tool0;
    MoveJ p1, v1000, fine, tool0;
    MoveL p2, v500, z10, tool0;
    MoveC pCir, p3, v500, fine, tool0;
    here := CPos(\Tool:=tool0);
    TPWrite "at x " \Num:=here.x;
  ENDPROC
ENDMODULE
