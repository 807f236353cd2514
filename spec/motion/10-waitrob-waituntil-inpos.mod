MODULE waitrob_waituntil_inpos
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @description After a fly-by move the program runs ahead of the robot (4.8 s, PP-flyby); WaitRob \InPos waits until the robot stands at the point (5 s, the last point of the queue is reached); WaitUntil \InPos evaluates its condition only when the robot stands still (doc/rulings.md R-4.1-f).
! @output ahead 4800
! @output WaitRob 5000
! @output WaitUntil 5500
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  PROC main()
    MoveJ p1, v1000, fine, tool0;
    ClkStart clk;
    MoveL p2, v100, z10, tool0;
    TPWrite "ahead " \Num:=Round(1000 * ClkRead(clk));
    WaitRob \InPos;
    TPWrite "WaitRob " \Num:=Round(1000 * ClkRead(clk));
    MoveL \Conc, Offs(p2, 0, 0, 50), v100, fine, tool0;
    WaitUntil \InPos, TRUE;
    TPWrite "WaitUntil " \Num:=Round(1000 * ClkRead(clk));
  ENDPROC
ENDMODULE
