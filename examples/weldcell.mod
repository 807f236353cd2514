%%%
  VERSION:1
  LANGUAGE:ENGLISH
%%%

MODULE WeldCell
  ! A small arc-welding cell on an ABB IRB 120: two fixtures an operator loads in turn, a welding
  ! torch switched by an output, a torch cleaner, and a safety door that pauses the robot.
  ! Signals and what the operator does are in examples/weldcell.io (doc/controller.md).
  !   di_part_ready  a part is clamped in the fixture       do_clamp   fixture clamp
  !   di_door        the safety door is open                do_arc     welding arc on
  !   do_clean       torch cleaner                          do_done    cycle done (pulse)

  RECORD seamdata
    num length;     ! mm, along x of the fixture
    num speed;      ! mm/s
    bool tack;
    string name;
    ! last line of the record may hold a comment of its own
  ENDRECORD

  ALIAS num millimetre;

  LOCAL CONST num MAX_CYCLES := 4;
  LOCAL CONST num MAX_RETRIES := 3;
  CONST jointtarget jHome := [[0,0,0,0,30,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
  CONST robtarget pClean := [[250,-250,350],[0,0,1,0],[-1,0,-1,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
  ! The seam start in each fixture's frame: the torch points down.
  CONST robtarget pSeam := [[0,0,0],[0,0,1,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
  PERS tooldata tTorch := [TRUE,[[0,0,100],[1,0,0,0]],[1.2,[0,0,50],[1,0,0,0],0,0,0]];
  PERS wobjdata wFixture1 := [FALSE,TRUE,"",[[250,-160,150],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
  PERS wobjdata wFixture2 := [FALSE,TRUE,"",[[250,60,150],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
  PERS seamdata seams{3} := [[120,20,FALSE,"left flange"],[95.5,25,TRUE,"rib"],[160,20,FALSE,"right flange"]];
  PERS num nCycles := 0;
  TASK PERS bool bSimulate := TRUE;
  VAR num nRetries := 0;
  VAR intnum iDoor;
  VAR clock cycleClock;
  VAR millimetre welded := 0;

  ! The entry routine: one cycle per part, the fixtures in turn.
  PROC main()
    VAR num fixture := 1;

    Init;
    WHILE nCycles < MAX_CYCLES DO
      WaitDI di_part_ready, 1 \MaxTime:=20;
      ClkReset cycleClock;
      ClkStart cycleClock;
      SetDO do_clamp, 1;
      TEST fixture
      CASE 1:
        WeldFixture wFixture1;
      CASE 2:
        WeldFixture wFixture2;
      DEFAULT:
        ErrWrite "Fixture", "Unknown fixture " + NumToStr(fixture, 0);
        EXIT;
      ENDTEST
      SetDO do_clamp, 0;
      PulseDO \PLength:=0.5, do_done;
      Incr nCycles;
      TPWrite "Cycle " + NumToStr(nCycles, 0) + " on fixture " + NumToStr(fixture, 0) + ", s:" \Num:=Round(ClkRead(cycleClock) \Dec:=1);
      fixture := fixture MOD 2 + 1;
      IF nCycles MOD 2 = 0 CleanTorch;
      MoveAbsJ jHome, v1000, z50, tTorch;
      ! The operator takes the part out before the next one comes.
      WaitDI di_part_ready, 0;
    ENDWHILE
    MoveAbsJ jHome, v1000, fine, tTorch;
    TPWrite "Cell done: " + NumToStr(nCycles, 0) + " parts, mm welded:" \Num:=welded;
  ERROR
    IF ERRNO = ERR_WAIT_MAXTIME THEN
      TPWrite "No part came: the cell stops";
      RETURN;
    ENDIF
  ENDPROC

  PROC Init()
    nRetries := 0;
    nCycles := 0;
    CONNECT iDoor WITH DoorTrap;
    ISignalDI di_door, 1, iDoor;
    MoveAbsJ jHome, v1000, fine, tTorch;
  ERROR
    IF ERRNO = ERR_ALRDYCNT THEN
      TRYNEXT;
    ENDIF
    RAISE;
  ENDPROC

  PROC WeldFixture(PERS wobjdata fixture)
    VAR num i;
    VAR robtarget pStart;

    FOR i FROM 1 TO Dim(seams, 1) DO
      IF seams{i}.tack AND (NOT bSimulate) THEN
        TPWrite "Tack weld: " + seams{i}.name;
      ELSEIF seams{i}.length > 150 THEN
        TPWrite "Long seam: " + seams{i}.name + ", mm " \Num:=seams{i}.length;
      ELSE
        TPWrite "Seam: " + seams{i}.name;
      ENDIF
      pStart := Offs(pSeam, 0, 30 * (i - 1), 0);
      MoveJ Offs(pStart, 0, 0, 50), v1000, z20, tTorch \WObj:=fixture;
      MoveL pStart, v200, fine, tTorch \WObj:=fixture;
      SetDO do_arc, 1;
      MoveL Offs(pStart, seams{i}.length, 0, 0), v100 \V:=seams{i}.speed, fine, tTorch \WObj:=fixture;
      SetDO do_arc, 0;
      welded := welded + seams{i}.length;
      MoveL Offs(pStart, seams{i}.length, 0, 50), v500, z20, tTorch \WObj:=fixture;
    ENDFOR
  ERROR (ERR_PATH_STOP)
    nRetries := nRetries + 1;
    IF nRetries <= MAX_RETRIES RETRY;
    RAISE;
  UNDO
    SetDO do_arc, 0;
  ENDPROC

  PROC CleanTorch()
    MoveJ pClean, v1000, fine, tTorch;
    %"Clean" + "Nozzle"%;
  ENDPROC

  PROC CleanNozzle()
    SetDO do_clean, 1;
    WaitTime \InPos, 1.5;
    SetDO do_clean, 0;
  ENDPROC

  FUNC num SeamTime(seamdata s)
    IF s.speed <= 0 RETURN 0;
    RETURN s.length / s.speed;
  ENDFUNC

  ! The safety door: the robot stops where it is until the door is closed again.
  TRAP DoorTrap
    StopMove;
    TPWrite "Door open: robot stopped";
    WaitDI di_door, 0;
    StartMove;
    TPWrite "Door closed: robot goes on";
  ENDTRAP
ENDMODULE
