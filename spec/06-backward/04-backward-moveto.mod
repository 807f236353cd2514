MODULE backward_moveto
! @format 3
! @section 6.3
! @expect ok
! @statement-time 0
! @description The routine MoveTo of section 6.3, whose BACKWARD handler mirrors its moves (with WaitRob and a report added after them). Run forward, MoveL p1, MoveC p2 p3 and MoveL p4 at v500 take 50 / 500 + 50 pi / 500 + 100 / 500 s: 0.614 s. Run backward (test/golden/debug-back-moveto.cmd, from the program pointer after MoveTo at 0.494 s, the look-ahead before p4's zone), the handler's moves retrace the forward path from its end (R-6.3-m): MoveL p4 from p4 back to p3, MoveC p2, p3 from p3 through p2 to p1, MoveL p1 from p1 to p0; the robot reaches p4 at 0.614 s, then needs 0.614 s more: at p0 at 1.228 s.
! @output forward at 300 100 300 t 614
  CONST robtarget p0 := [[300,-150,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p1 := [[300,-100,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[350,-50,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p3 := [[300,0,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p4 := [[300,100,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS tooldata tool1 := [TRUE,[[0,0,0],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];
  VAR clock clk;
  PROC main()
    MoveJ p0, v1000, fine, tool1;
    ClkStart clk;
    MoveTo;
    WaitRob \InPos;
    report "forward";
  ENDPROC
  PROC MoveTo()
    MoveL p1, v500, z10, tool1;
    MoveC p2, p3, v500, z10, tool1;
    MoveL p4, v500, z10, tool1;
  BACKWARD
    MoveL p4, v500, z10, tool1;
    MoveC p2, p3, v500, z10, tool1;
    MoveL p1, v500, z10, tool1;
    WaitRob \InPos;
    report "backward";
  ENDPROC
  PROC report(string what)
    VAR pos here;
    here := CPos(\Tool:=tool1);
    TPWrite what + " at " + NumToStr(here.x, 0) + " " + NumToStr(here.y, 0) + " " + NumToStr(here.z, 0) + " t " + NumToStr(1000 * ClkRead(clk), 0);
  ENDPROC
ENDMODULE
