MODULE clearpath_in_trap
! @format 3
! @section 13
! @section 8
! @expect ok
! @description ClearPath in a trap, while the second of two fly-by moves is planned but not begun: the path is cleared (the second move dropped at the time of ClearPath), StartMove lets the robot go on, and the program goes on after the trap. Both engines write the same motion events, the drop's time included.
! @output cleared
! @output done
  CONST robtarget p1 := [[400,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[400,200,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR intnum t1;
  TRAP stop_and_clear
    StopMove;
    ClearPath;
    StartMove;
    TPWrite "cleared";
  ENDTRAP
  PROC main()
    CONNECT t1 WITH stop_and_clear;
    ITimer \Single, 1.75, t1;
    MoveJ p1, v100, z50, tool0;
    MoveJ p2, v100, z50, tool0;
    TPWrite "done";
  ENDPROC
ENDMODULE
