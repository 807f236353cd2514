MODULE moveextj_case
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @description MoveExtJ moves the external axes only (ABB, RAPID Instructions); the robot of the run (the IRB 120) has none, so MoveExtJ with every external axis unused (9E9) moves no axis (R-4.1-n): the arm stays where the last move put it and the active tool stays the last move's; a stop point waits until the robot stands still (the MoveL \\Conc before it: 100 mm at v100, 1 s), it takes no time of its own, or \\T seconds.
! @output ext at 1000 y -150 tool1 TRUE
! @output ext T at 3000 y -150
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,-150,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget no_ext := [[0,0,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS tooldata tool1 := [TRUE,[[0,0,100],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];
  VAR clock clk;
  PROC main()
    VAR pos p;
    MoveJ Offs(p1, 0, 0, -100), v1000, fine, tool1;
    ClkStart clk;
    MoveL \Conc, Offs(p2, 0, 0, -100), v100, fine, tool1;
    MoveExtJ no_ext, v1000, fine;
    p := CPos(\Tool:=tool1);
    TPWrite "ext at " + NumToStr(1000 * ClkRead(clk), 0) + " y " + NumToStr(p.y, 0) + " tool1 " \Bool:=(CTool() = tool1);
    MoveExtJ no_ext, v1000 \T:=2, fine;
    p := CPos(\Tool:=tool1);
    TPWrite "ext T at " + NumToStr(1000 * ClkRead(clk), 0) + " y " + NumToStr(p.y, 0);
  ENDPROC
ENDMODULE
