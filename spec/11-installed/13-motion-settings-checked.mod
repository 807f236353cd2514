MODULE motion_settings_checked
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @description SoftAct, SoftDeact and PathAccLim (ABB's RAPID reference: SoftAct [\MechUnit] Axis Softness [\Ramp], Softness 0 - 100 %, \Ramp >= 100 %; PathAccLim AccLim [\AccMax] DecelLim [\DecelMax] in m/s2; ABB's own examples) are checked and change nothing of rapid-sem's constant-speed motion (doc/rulings.md R-13-sys5, R-4.1-g): the 500 mm MoveL at v100 still takes 5 s. MaxRobReorientSpeed is vmax's reorientation speed, 500 degrees/s. Out of range, each is ERR_ARGVALERR; an axis that is not an integer ERR_NOTINTVAL.
! @output t 5000
! @output reorient 500
! @output axis 7 ERR_ARGVALERR
! @output axis 1.5 ERR_NOTINTVAL
! @output softness 101 ERR_ARGVALERR
! @output ramp 99 ERR_ARGVALERR
! @output deact ramp 50 ERR_ARGVALERR
! @output acclim without AccMax ERR_ARGVALERR
! @output decelmax 0 ERR_ARGVALERR
! @output accmax with the limit off no error
  CONST robtarget p1 := [[300,-250,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget p2 := [[300,250,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR clock clk;
  PROC main()
    SoftAct 3, 20;
    SoftAct 1, 90 \Ramp:=150;
    SoftAct \MechUnit:=ROB_1, 1, 40 \Ramp:=120;
    PathAccLim TRUE \AccMax:=4, TRUE \DecelMax:=4;
    MoveJ p1, v1000, fine, tool0;
    ClkStart clk;
    MoveL p2, v100, fine, tool0;
    TPWrite "t " \Num:=Round(1000 * ClkRead(clk));
    SoftDeact \Ramp:=150;
    SoftDeact;
    PathAccLim FALSE, FALSE;
    PathAccLim TRUE \AccMax:=4, FALSE;
    TPWrite "reorient " \Num:=MaxRobReorientSpeed();
    Try "axis 7", 1;
    Try "axis 1.5", 2;
    Try "softness 101", 3;
    Try "ramp 99", 4;
    Try "deact ramp 50", 5;
    Try "acclim without AccMax", 6;
    Try "decelmax 0", 7;
    Try "accmax with the limit off", 8;
  ENDPROC
  PROC Try(string what, num which)
    TEST which
    CASE 1:
      SoftAct 7, 50;
    CASE 2:
      SoftAct 1.5, 50;
    CASE 3:
      SoftAct 2, 101;
    CASE 4:
      SoftAct 2, 50 \Ramp:=99;
    CASE 5:
      SoftDeact \Ramp:=50;
    CASE 6:
      PathAccLim TRUE, FALSE;
    CASE 7:
      PathAccLim FALSE, TRUE \DecelMax:=0;
    CASE 8:
      PathAccLim FALSE \AccMax:=-1, FALSE;
    ENDTEST
    TPWrite what + " no error";
  ERROR
    IF ERRNO = ERR_ARGVALERR TPWrite what + " ERR_ARGVALERR";
    IF ERRNO = ERR_NOTINTVAL TPWrite what + " ERR_NOTINTVAL";
    RETURN;
  ENDPROC
ENDMODULE
