MODULE searchl_case
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @io io/search.io
! @description SearchL \Stop (ABB, RAPID Instructions): a linear search towards p2 at v100; the sensor di_part goes to 1 after 2 s, 200 mm along: SearchPoint takes that position, the robot stops there and the rest of the path is dropped. A second search finds no positive flank (the signal stays 1): ERR_WHLSEARCH, after the robot reached the end of that search.
! @output hit at 2000 y -50
! @output robot y -50
! @output ERR_WHLSEARCH at 2500 y 0
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  PROC main()
    VAR robtarget found;
    VAR pos p;
    MoveJ p1, v1000, fine, tool0;
    ClkStart clk;
    SearchL \Stop, di_part, found, p2, v100, tool0;
    TPWrite "hit at " + NumToStr(1000 * ClkRead(clk), 0) + " y " + NumToStr(found.trans.y, 0);
    p := CPos(\Tool:=tool0);
    TPWrite "robot y " \Num:=Round(p.y);
    SearchL \Stop, di_part, found, Offs(p1, 0, 250, 0), v100, tool0;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_WHLSEARCH THEN
      p := CPos(\Tool:=tool0);
      TPWrite "ERR_WHLSEARCH at " + NumToStr(1000 * ClkRead(clk), 0) + " y " + NumToStr(p.y, 0);
      RETURN;
    ENDIF
  ENDPROC
ENDMODULE
