MODULE backward_handler_forward
! @format 3
! @section 6.3
! @expect ok
! @statement-time 0
! @description The routine of section 6.3 run forwards: a routine with a BACKWARD handler executes its body (the handler mirrors the moves for backward execution, which this run does not do); MoveL p1, MoveC p2 p3 and MoveL p4 at v500 with z10 take 50 / 500 + (50 pi) / 500 + 100 / 500 s together: 0.614 s (T-cartesian; zones take no time, Z-corner), and the robot ends at p4.
! @output t 614
! @output at 300.0 100.0 300.0
  CONST robtarget p0 := [[300,-150,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p1 := [[300,-100,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[350,-50,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p3 := [[300,0,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p4 := [[300,100,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS tooldata tool1 := [TRUE,[[0,0,0],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];
  VAR clock clk;
  PROC main()
    VAR pos here;
    MoveJ p0, v1000, fine, tool1;
    ClkStart clk;
    MoveTo;
    WaitRob \InPos;
    TPWrite "t " \Num:=Round(1000 * ClkRead(clk));
    here := CPos(\Tool:=tool1);
    TPWrite "at " + NumToStr(here.x, 1) + " " + NumToStr(here.y, 1) + " " + NumToStr(here.z, 1);
  ENDPROC
  PROC MoveTo()
    MoveL p1, v500, z10, tool1;
    MoveC p2, p3, v500, z10, tool1;
    MoveL p4, v500, z10, tool1;
  BACKWARD
    MoveL p4, v500, z10, tool1;
    MoveC p2, p3, v500, z10, tool1;
    MoveL p1, v500, z10, tool1;
  ENDPROC
ENDMODULE
