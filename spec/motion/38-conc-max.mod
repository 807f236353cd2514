MODULE conc_max
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @description At most five \\Conc moves follow each other (ABB, MoveL \\Conc; installed-facts.md section 5): six MoveL \\Conc of 100 mm at v100 to stop points; each lets the program pointer go on when its motion begins (PP-conc), at 0, 1, 2, 3 and 4 s; the sixth, at 4 s, is refused with ERR_CONC_MAX before it is planned (R-4.1-m). The handler waits for the robot (WaitRob \\InPos: the fifth move ends at 5 s), which ends the run of \\Conc moves, and RETRY plans the sixth, back to p1: 5 s to 6 s.
! @output ERR_CONC_MAX at 4000
! @output done at 6000 y -250
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,-150,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  PROC main()
    VAR pos p;
    MoveJ p1, v1000, fine, tool0;
    ClkStart clk;
    MoveL \Conc, p2, v100, fine, tool0;
    MoveL \Conc, p1, v100, fine, tool0;
    MoveL \Conc, p2, v100, fine, tool0;
    MoveL \Conc, p1, v100, fine, tool0;
    MoveL \Conc, p2, v100, fine, tool0;
    MoveL \Conc, p1, v100, fine, tool0;
    WaitRob \InPos;
    p := CPos(\Tool:=tool0);
    TPWrite "done at " + NumToStr(1000 * ClkRead(clk), 0) + " y " + NumToStr(p.y, 0);
  ERROR
    IF ERRNO = ERR_CONC_MAX THEN
      TPWrite "ERR_CONC_MAX at " \Num:=Round(1000 * ClkRead(clk));
      WaitRob \InPos;
      RETRY;
    ENDIF
  ENDPROC
ENDMODULE
