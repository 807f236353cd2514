MODULE base_frame_moved
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @base-frame 1000,500,200,1,0,0,0
! @description The cell mounts the robot with its base frame at [1000,500,200] in the world, not turned (MOC.cfg's ROBOT -base_frame_pos_*, --base-frame; law F-base, R-bk-12). Robtargets in wobj0 are in the world: at the axes home the flange stands at [302,0,558] in the base frame, so CRobT reads [1302,500,758]. p1, 100 mm below, is 1400 mm from the world's origin, beyond the arm's reach from there, and is reached (v100: 1 s); CalcJointT of it is the axes reached. A work object at [1000,500,0] in the world: a target [302,0,658] in it is the same point, and CRobT and CPos in it read the work object's coordinates.
! @output home 1302 500 758
! @output calc 1302 500 758
! @output t 1000 at 1302 500 658
! @output calcjoint TRUE
! @output wobj 302 0 658 pos 302 0 658
! @output again 0
  CONST jointtarget home := [[0,0,0,0,90,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p1 := [[1302,500,658],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget q1 := [[302,0,658],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS wobjdata table := [FALSE,TRUE,"",[[1000,500,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
  VAR clock clk;
  PROC show(string label, pos p)
    TPWrite label + " " + NumToStr(p.x, 0) + " " + NumToStr(p.y, 0) + " " + NumToStr(p.z, 0);
  ENDPROC
  PROC main()
    VAR robtarget r;
    VAR jointtarget j;
    VAR jointtarget jc;
    VAR pos p;
    MoveAbsJ home, v1000, fine, tool0;
    r := CRobT(\Tool:=tool0 \WObj:=wobj0);
    show "home", r.trans;
    r := CalcRobT(home, tool0);
    show "calc", r.trans;
    ClkStart clk;
    MoveL p1, v100, fine, tool0;
    r := CRobT(\Tool:=tool0);
    TPWrite "t " + NumToStr(Round(1000 * ClkRead(clk)), 0) + " at " + NumToStr(r.trans.x, 0) + " " + NumToStr(r.trans.y, 0) + " " + NumToStr(r.trans.z, 0);
    j := CJointT();
    jc := CalcJointT(p1, tool0);
    TPWrite "calcjoint " \Bool := Abs(j.robax.rax_2 - jc.robax.rax_2) < 0.01 AND Abs(j.robax.rax_3 - jc.robax.rax_3) < 0.01 AND Abs(j.robax.rax_5 - jc.robax.rax_5) < 0.01;
    r := CRobT(\Tool:=tool0 \WObj:=table);
    p := CPos(\Tool:=tool0 \WObj:=table);
    TPWrite "wobj " + NumToStr(r.trans.x, 0) + " " + NumToStr(r.trans.y, 0) + " " + NumToStr(r.trans.z, 0) + " pos " + NumToStr(p.x, 0) + " " + NumToStr(p.y, 0) + " " + NumToStr(p.z, 0);
    ClkReset clk;
    ClkStart clk;
    MoveL q1, v100, fine, tool0 \WObj:=table;
    TPWrite "again " + NumToStr(Round(1000 * ClkRead(clk)), 0);
  ENDPROC
ENDMODULE
