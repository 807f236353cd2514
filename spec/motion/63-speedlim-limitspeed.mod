MODULE speedlim_limitspeed
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @io io/limitspeed.io
! @description SpeedLimCheckPoint and SpeedLimAxis (ABB, RAPID Instructions) limit the checkpoints' and an axis's speed while the system input LimitSpeed is active (doc/rulings.md R-13-speedlim1). Before di_lim is 1, a 200 mm MoveL at v1000 takes 0.2 s despite SpeedLimCheckPoint 100; once it is 1, the same path back takes 2 s (100 mm/s), and with SpeedLimAxis ROB_1, 1, 10 a MoveAbsJ of axis 1 by 30 degrees takes 3 s. A speed below 0 is ERR_SPEEDLIM_VALUE, an axis 7 ERR_ARGVALERR.
! @output free 200
! @output limited 2000
! @output axis 3000
! @output ERR_SPEEDLIM_VALUE
! @output ERR_ARGVALERR
  CONST robtarget p1 := [[300,-100,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget j0 := [[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget j1 := [[30,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  VAR num stage := 0;
  PROC main()
    MoveJ p1, v1000, fine, tool0;
    SpeedLimCheckPoint 100;
    ClkStart clk;
    MoveL Offs(p1, 0, 200, 0), v1000, fine, tool0;
    TPWrite "free " \Num:=Round(1000 * ClkRead(clk));
    WaitDI di_lim, 1;
    ClkReset clk;
    ClkStart clk;
    MoveL p1, v1000, fine, tool0;
    TPWrite "limited " \Num:=Round(1000 * ClkRead(clk));
    MoveAbsJ j0, v1000, fine, tool0;
    SpeedLimAxis ROB_1, 1, 10;
    ClkReset clk;
    ClkStart clk;
    MoveAbsJ j1, v1000, fine, tool0;
    TPWrite "axis " \Num:=Round(1000 * ClkRead(clk));
    stage := 1;
    SpeedLimCheckPoint -1;
    stage := 2;
    SpeedLimAxis ROB_1, 7, 10;
  ERROR
    IF ERRNO = ERR_SPEEDLIM_VALUE THEN
      TPWrite "ERR_SPEEDLIM_VALUE";
      TRYNEXT;
    ELSEIF ERRNO = ERR_ARGVALERR THEN
      TPWrite "ERR_ARGVALERR";
      TRYNEXT;
    ENDIF
  ENDPROC
ENDMODULE
