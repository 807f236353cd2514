MODULE GlueProcess
    ! Glue bead application on door inner panels with a stationary pump and a gun on the
    ! robot. The gun is opened and closed on the path with TriggL/TriggIO so the bead
    ! starts and ends where it should, whatever the speed. The glue level and the gun
    ! pressure are checked; a failure anywhere in a bead jumps back to the recovery
    ! point in GlueCycle, which purges the gun and does the bead again.

    LOCAL ALIAS num percent;

    RECORD BeadSpec
        string name;
        num speed;          ! mm/s along the bead
        percent flow;       ! of the pump maximum
        num startAhead;     ! s the gun opens before the first point
        num stopAhead;      ! mm the gun closes before the last point
    ENDRECORD

    CONST BeadSpec beadFlange := ["flange", 180, 65, 0.08, 12];
    CONST BeadSpec beadHem := ["hem", 120, 80, 0.1, 8];

    ! User error numbers (1..90) for the long jump to GlueCycle.
    CONST errnum GLUE_ERR_LEVEL := 41;
    CONST errnum GLUE_ERR_PRESSURE := 42;

    CONST num MAX_BEAD_REPEATS := 2;

    PERS tooldata tGlueGun := [TRUE, [[35.2, 0, 312.8], [0.906308, 0, 0.422618, 0]],
                               [4.1, [10, 0, 120], [1, 0, 0, 0], 0.02, 0.02, 0.01]];
    PERS wobjdata wobjDoor := [FALSE, TRUE, "", [[1320, -75, 560], [1, 0, 0, 0]],
                               [[0, 0, 0], [1, 0, 0, 0]]];

    CONST robtarget pPurge := [[650, -900, 420], [0, 0, 1, 0], [-1, 0, 0, 0],
                               [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]];
    CONST robtarget pFlange{6} := [
        [[20, 15, 5], [0, 0.707107, 0.707107, 0], [0, 0, 0, 0], [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]],
        [[620, 15, 5], [0, 0.707107, 0.707107, 0], [0, 0, 0, 0], [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]],
        [[820, 60, 5], [0, 0.707107, 0.707107, 0], [0, 0, 0, 0], [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]],
        [[860, 260, 5], [0, 0.707107, 0.707107, 0], [0, 0, 0, 0], [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]],
        [[820, 460, 5], [0, 0.707107, 0.707107, 0], [0, 0, 0, 0], [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]],
        [[20, 505, 5], [0, 0.707107, 0.707107, 0], [0, 0, 0, 0], [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]]];
    CONST robtarget pHem{4} := [
        [[40, 40, 2], [0, 0.707107, 0.707107, 0], [0, 0, 0, 0], [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]],
        [[780, 40, 2], [0, 0.707107, 0.707107, 0], [0, 0, 0, 0], [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]],
        [[780, 480, 2], [0, 0.707107, 0.707107, 0], [0, 0, 0, 0], [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]],
        [[40, 480, 2], [0, 0.707107, 0.707107, 0], [0, 0, 0, 0], [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]]];

    VAR triggdata gunOn;
    VAR triggdata gunOff;
    VAR intnum intGluePressure;
    VAR num beadRepeats := 0;
    VAR bool gunOpen := FALSE;
    PERS num beadsDone := 0;
    PERS num gluePurges := 0;

    ! One door panel. A failure in a bead long-jumps here; the bead is done again.
    PROC GlueCycle()
        beadRepeats := 0;
        GlueCheckLevel;
        GlueArmPressure;
        GlueBead pFlange, beadFlange;
        GlueBead pHem, beadHem;
        IDelete intGluePressure;
    ERROR (GLUE_ERR_LEVEL, GLUE_ERR_PRESSURE)
        GlueCloseGun;
        IF ERRNO = GLUE_ERR_LEVEL THEN
            TPWrite "Glue level low: change the drum, then press start";
            Stop;
            RETRY;
        ENDIF
        Incr beadRepeats;
        IF beadRepeats > MAX_BEAD_REPEATS THEN
            ErrWrite "Glue", "Pressure fault repeated, part rejected";
            SetDO doPartReject, 1;
            IDelete intGluePressure;
            RETURN;
        ENDIF
        GluePurge;
        RETRY;
    ENDPROC

    ! Applies one bead through the points. The gun opens startAhead seconds before the
    ! first point and closes stopAhead mm before the last one.
    PROC GlueBead(robtarget points{*}, BeadSpec bead)
        VAR speeddata beadSpeed := [100, 200, 5000, 1000];
        VAR num last;

        last := Dim(points, 1);
        beadSpeed.v_tcp := bead.speed;
        SetAO aoGlueFlow, bead.flow;
        TriggIO gunOn, bead.startAhead \Time \DOp:=doGlueGun, 1;
        TriggIO gunOff, bead.stopAhead \Start \DOp:=doGlueGun, 0;
        GlueApproach points{1};
        TriggL points{1}, beadSpeed, gunOn, z1, tGlueGun \WObj:=wobjDoor;
        gunOpen := TRUE;
        FOR i FROM 2 TO last - 1 DO
            MoveL points{i}, beadSpeed, z5, tGlueGun \WObj:=wobjDoor;
        ENDFOR
        TriggL points{last}, beadSpeed, gunOff, fine, tGlueGun \WObj:=wobjDoor;
        gunOpen := FALSE;
        MoveL Offs(points{last}, 0, 0, 80), v500, z20, tGlueGun \WObj:=wobjDoor;
        Incr beadsDone;
    UNDO
        ! Left by a long jump or a moved program pointer: the gun must not stay open.
        GlueCloseGun;
    ENDPROC

    ! Stepping backwards retraces the approach with the same moves in reverse order
    ! (§6.3) and never dispenses.
    PROC GlueApproach(robtarget first)
        MoveJ Offs(first, 0, 0, 80), v1000, z20, tGlueGun \WObj:=wobjDoor;
        MoveL Offs(first, 0, 0, 10), v300, z5, tGlueGun \WObj:=wobjDoor;
    BACKWARD
        SetDO doGlueGun, 0;
        MoveL Offs(first, 0, 0, 10), v300, z5, tGlueGun \WObj:=wobjDoor;
        MoveJ Offs(first, 0, 0, 80), v1000, z20, tGlueGun \WObj:=wobjDoor;
    ENDPROC

    PROC GlueCloseGun()
        SetDO doGlueGun, 0;
        SetAO aoGlueFlow, 0;
        gunOpen := FALSE;
    ENDPROC

    ! Purges the gun into the cup; the glue on the nozzle would spoil the next bead.
    PROC GluePurge()
        MoveJ Offs(pPurge, 0, 0, 100), v1000, z20, tGlueGun;
        MoveL pPurge, v200, fine, tGlueGun;
        SetAO aoGlueFlow, 50;
        SetDO doGlueGun, 1;
        WaitTime 1.5;
        GlueCloseGun;
        MoveL Offs(pPurge, 0, 0, 100), v500, z20, tGlueGun;
        Incr gluePurges;
    BACKWARD
        GlueCloseGun;
        MoveL Offs(pPurge, 0, 0, 100), v500, z20, tGlueGun;
        MoveL pPurge, v200, fine, tGlueGun;
        MoveJ Offs(pPurge, 0, 0, 100), v1000, z20, tGlueGun;
    ENDPROC

    PROC GlueCheckLevel()
        IF DInput(diGlueLevelLow) = 1 RAISE GLUE_ERR_LEVEL;
    ENDPROC

    ! The pressure switch opens while the gun is open when the pump fails.
    PROC GlueArmPressure()
        IDelete intGluePressure;
        CONNECT intGluePressure WITH GluePressureTrap;
        ISignalDI \Single, diGluePressureOk, 0, intGluePressure;
    ENDPROC

    ! Stops the robot on the path and long-jumps to the recovery point in GlueCycle.
    TRAP GluePressureTrap
        IF NOT gunOpen RETURN;
        StopMove;
        ClearPath;
        StartMove;
        SetDO doGlueGun, 0;
        RAISE GLUE_ERR_PRESSURE;
    ENDTRAP
ENDMODULE
