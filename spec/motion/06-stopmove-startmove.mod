MODULE stopmove_startmove
! @format 3
! @section 8
! @expect ok
! @statement-time 0
! @description StopMove in a trap 2 s into a 5 s move stops the robot where it is (S-stop, no deceleration in the constant-speed model); the trap waits 1 s and StartMove resumes the path: the move ends 1 s late, at 6 s, and the robot stood at y = -50 meanwhile.
! @output stopped y -50
! @output end 6000
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  VAR intnum tick;
  TRAP pause
    VAR pos p;
    StopMove;
    WaitTime 1;
    p := CPos(\Tool:=tool0);
    TPWrite "stopped y " \Num:=Round(p.y);
    StartMove;
  ENDTRAP
  PROC main()
    MoveJ p1, v1000, fine, tool0;
    ClkStart clk;
    CONNECT tick WITH pause;
    ITimer \Single, 2, tick;
    MoveL p2, v100, fine, tool0;
    TPWrite "end " \Num:=Round(1000 * ClkRead(clk));
  ENDPROC
ENDMODULE
