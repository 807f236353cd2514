MODULE searchc_searchj
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @io io/search.io
! @description SearchC and SearchJ (ABB, RAPID Instructions), as SearchL (M-search): SearchC \\Stop from p1 on the half circle of radius 100 about [300,-150,300] through c1 to p3 at v100 (1 rad/s, G-circle); the sensor sees the part 2 s after the search begins: SearchPoint takes the TCP there, 2 rad along the arc, [300 + 100 sin 2, -150 - 100 cos 2, 300] = [390.9, -108.4, 300], and the robot stops there. SearchJ \\Sup back to p1 with \\T:=2 finds no positive flank (the signal stays 1): the robot reaches p1 at 4 s and ERR_WHLSEARCH is raised. SearchJ \\Stop \\HighLevel hits at once: SearchPoint is where the robot stands.
! @output hit at 2000 x 391 y -108
! @output robot x 391 y -108
! @output ERR_WHLSEARCH at 4000 x 300 y -250
! @output level hit at 4000 y -250
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget c1 := [[400,-150,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p3 := [[300,-50,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  PROC main()
    VAR robtarget found;
    VAR pos p;
    MoveJ p1, v1000, fine, tool0;
    ClkStart clk;
    SearchC \Stop, di_part, found, c1, p3, v100, tool0;
    TPWrite "hit at " + NumToStr(1000 * ClkRead(clk), 0) + " x " + NumToStr(found.trans.x, 0) + " y " + NumToStr(found.trans.y, 0);
    p := CPos(\Tool:=tool0);
    TPWrite "robot x " + NumToStr(p.x, 0) + " y " + NumToStr(p.y, 0);
    back;
    SearchJ \Stop, di_part \HighLevel, found, p3, v100, tool0;
    TPWrite "level hit at " + NumToStr(1000 * ClkRead(clk), 0) + " y " + NumToStr(found.trans.y, 0);
  ENDPROC
  PROC back()
    VAR robtarget found;
    VAR pos p;
    SearchJ \Sup, di_part, found, p1, v100 \T:=2, tool0;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_WHLSEARCH THEN
      p := CPos(\Tool:=tool0);
      TPWrite "ERR_WHLSEARCH at " + NumToStr(1000 * ClkRead(clk), 0) + " x " + NumToStr(p.x, 0) + " y " + NumToStr(p.y, 0);
      RETURN;
    ENDIF
  ENDPROC
ENDMODULE
