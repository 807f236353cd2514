MODULE storepath_restopath
! @format 3
! @section 8
! @expect ok
! @statement-time 0
! @description A trap 2 s into a 5 s move: StopMove, StorePath (path level 2, S-level), a 50 mm move up and back (0.5 s each), RestoPath (level 1 again) and StartMove: the interrupted move goes on and ends 1 s late.
! @output level 2
! @output level 1
! @output end 6000
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  VAR intnum tick;
  TRAP service
    VAR robtarget here;
    StopMove;
    StorePath;
    TPWrite "level " \Num:=PathLevel();
    here := CRobT(\Tool:=tool0);
    MoveL Offs(here, 0, 0, 50), v100, fine, tool0;
    MoveL here, v100, fine, tool0;
    RestoPath;
    TPWrite "level " \Num:=PathLevel();
    StartMove;
  ENDTRAP
  PROC main()
    MoveJ p1, v1000, fine, tool0;
    ClkStart clk;
    CONNECT tick WITH service;
    ITimer \Single, 2, tick;
    MoveL p2, v100, fine, tool0;
    TPWrite "end " \Num:=Round(1000 * ClkRead(clk));
  ENDPROC
ENDMODULE
