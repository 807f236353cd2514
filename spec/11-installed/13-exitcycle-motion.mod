MODULE exit_cycle_motion
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @description ExitCycle stops the robot's on-going movement and drops every path not done (ABB's ExitCycle; doc/rulings.md R-13-exitcycle1): in the first cycle two moves with zones are given (the program pointer runs ahead of the robot to the second move's zone, doc/motion.md) and ExitCycle comes while the robot is on its way to b (axis 6 at about 131 degrees); in the second cycle, 2 s later (b would have been reached), the robot stands where ExitCycle found it, short of b; a new move then goes from there.
! @output cycle 1
! @output cycle 2: the robot stood short of b TRUE
! @output then axis 6 45
  VAR num cycle := 0;
  CONST jointtarget a := [[0, 0, 0, 0, 0, 90], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST jointtarget b := [[0, 0, 0, 0, 0, 180], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST jointtarget c := [[0, 0, 0, 0, 0, 45], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    VAR jointtarget j;
    Incr cycle;
    IF cycle = 1 THEN
      TPWrite "cycle 1";
      MoveAbsJ a, v100, z50, tool0;
      MoveAbsJ b, v100, z50, tool0;
      ExitCycle;
    ENDIF
    WaitTime 2;
    j := CJointT();
    TPWrite "cycle 2: the robot stood short of b " \Bool:=j.robax.rax_6 < 170;
    MoveAbsJ c, v1000, fine, tool0;
    j := CJointT();
    TPWrite "then axis 6 " + NumToStr(j.robax.rax_6, 0);
  ENDPROC
ENDMODULE
