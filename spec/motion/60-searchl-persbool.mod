MODULE searchl_persbool
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @description SearchL Signal | PersBool (ABB, RAPID Instructions, RobotWare 6 and later): the search watches a persistent bool as it watches a digital input. A timer trap sets bTouch after 2 s, 200 mm along at v100: SearchPoint takes that position and \SStop leaves the robot there. A second search with \PersBool:= named finds no positive flank (bTouch stays TRUE): ERR_WHLSEARCH at the end of that search.
! @output hit at 2000 y -50
! @output robot y -50
! @output ERR_WHLSEARCH at 2500 y 0
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS bool bTouch := FALSE;
  VAR clock clk;
  VAR intnum tick;
  TRAP touch
    bTouch := TRUE;
  ENDTRAP
  PROC main()
    VAR robtarget found;
    VAR pos p;
    bTouch := FALSE;
    MoveJ p1, v1000, fine, tool0;
    CONNECT tick WITH touch;
    ITimer \Single, 2, tick;
    ClkStart clk;
    SearchL \SStop, bTouch, found, p2, v100, tool0;
    TPWrite "hit at " + NumToStr(1000 * ClkRead(clk), 0) + " y " + NumToStr(found.trans.y, 0);
    p := CPos(\Tool:=tool0);
    TPWrite "robot y " \Num:=Round(p.y);
    SearchL \Stop, PersBool:=bTouch, found, Offs(p1, 0, 250, 0), v100, tool0;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_WHLSEARCH THEN
      p := CPos(\Tool:=tool0);
      TPWrite "ERR_WHLSEARCH at " + NumToStr(1000 * ClkRead(clk), 0) + " y " + NumToStr(p.y, 0);
      RETURN;
    ENDIF
  ENDPROC
ENDMODULE
