MODULE settings_accepted
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @description AccSet, CornerPathWarning, GripLoad and StopMoveReset are accepted and change nothing (doc/rulings.md R-4.1-g): the 500 mm MoveL at v100 still takes 5 s. ConfJ, ConfL and SingArea set the planner's settings; CTool and CWObj are those of the last move; CSpeedOverride is 100.
! @output t 5000
! @output tool z 100
! @output wobj x 10
! @output override 100
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS tooldata tPen := [TRUE,[[0,0,100],[1,0,0,0]],[1,[0,0,50],[1,0,0,0],0,0,0]];
  PERS wobjdata wTable := [FALSE,TRUE,"",[[10,0,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
  VAR clock clk;
  PROC main()
    VAR tooldata t;
    VAR wobjdata w;
    AccSet 50, 50;
    CornerPathWarning FALSE;
    GripLoad load0;
    StopMoveReset;
    ConfJ \On;
    ConfL \On;
    SingArea \Wrist;
    MoveJ p1, v1000, fine, tool0;
    ClkStart clk;
    MoveL p2, v100, fine, tool0;
    TPWrite "t " \Num:=Round(1000 * ClkRead(clk));
    MoveL Offs(p2, -10, 0, -100), v100, fine, tPen \WObj:=wTable;
    t := CTool();
    w := CWObj();
    TPWrite "tool z " \Num:=t.tframe.trans.z;
    TPWrite "wobj x " \Num:=w.uframe.trans.x;
    TPWrite "override " \Num:=CSpeedOverride();
  ENDPROC
ENDMODULE
