%%%
  VERSION:1
  LANGUAGE:ENGLISH
%%%

MODULE WeldCell
  ! A small arc-welding cell: two fixtures, a torch cleaner and an operator panel.
  ! Written for rapid-sem's examples; the installed routines it calls (MoveL, ArcL,
  ! WaitDI, ...) belong to the robot system, not to the RAPID kernel.

  RECORD seamdata
    num length;     ! mm
    num speed;      ! mm/s
    bool tack;
    string name;
    ! last line of the record may hold a comment of its own
  ENDRECORD

  ALIAS num millimetre;

  LOCAL CONST num MAX_RETRIES := 3;
  CONST robtarget pHome := [[600,0,850],[0.70711,0,0.70711,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
  CONST robtarget pClean := [[412.5,-620.25,700],[0.5,-0.5,0.5,0.5],[-1,0,-1,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
  PERS seamdata seams{3} := [[120,8.5,FALSE,"left flange"],[95.5,7,TRUE,"rib"],[200,9,FALSE,"right flange"]];
  PERS num nCycles := 0;
  TASK PERS bool bSimulate := TRUE;
  VAR num nRetries := 0;
  VAR intnum iStop;
  VAR string sLog;

  ! The entry routine: one cycle per part until the operator stops the cell.
  PROC main()
    VAR num fixture := 1;

    Init;
    WHILE TRUE DO
      TEST fixture
      CASE 1, 2:
        WeldFixture fixture;
      DEFAULT:
        ErrWrite "Fixture", "Unknown fixture " + NumToStr(fixture, 0);
        EXIT;
      ENDTEST
      fixture := fixture MOD 2 + 1;
      Incr nCycles;
      IF nCycles MOD 20 = 0 CleanTorch;
    ENDWHILE
  ENDPROC

  PROC Init()
    nRetries := 0;
    CONNECT iStop WITH StopTrap;
    MoveJ pHome, v1000, fine, tool0;
  ERROR
    IF ERRNO = ERR_ALRDYCNT THEN
      TRYNEXT;
    ENDIF
    RAISE;
  ENDPROC

  PROC WeldFixture(num fixture)
    VAR num i;
    VAR robtarget pStart;

    FOR i FROM 1 TO Dim(seams, 1) DO
      IF seams{i}.tack AND (NOT bSimulate) THEN
        TPWrite "Tack weld: " + seams{i}.name;
      ELSEIF seams{i}.length > 150 THEN
        TPWrite "Long seam: " + seams{i}.name \Num:=seams{i}.length;
      ELSE
        TPWrite "Seam: " + seams{i}.name;
      ENDIF
      pStart := Offs(pHome, -seams{i}.length / 2, 100 * (fixture - 1), -400);
      MoveL pStart, v500, z10, tool0\WObj:=wobj0;
      MoveL Offs(pStart, seams{i}.length, 0, 0), v100, fine, tool0\WObj:=wobj0;
    ENDFOR
  ERROR (ERR_PATH_STOP)
    nRetries := nRetries + 1;
    IF nRetries <= MAX_RETRIES RETRY;
    RAISE;
  UNDO
    MoveJ pHome, v1000, fine, tool0;
  ENDPROC

  PROC CleanTorch()
    MoveJ pClean, v1000, z50, tool0;
    %"Clean" + "Nozzle"%;
  ENDPROC

  FUNC num SeamTime(seamdata s)
    IF s.speed <= 0 RETURN 0;
    RETURN s.length / s.speed;
  ENDFUNC

  TRAP StopTrap
    TPWrite "Stop requested after " \Num:=nCycles;
    EXIT;
  ENDTRAP
ENDMODULE
