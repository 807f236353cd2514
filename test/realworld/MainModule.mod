MODULE MainModule
    ! Main program of station 30. The PLC chooses the part type on goPartType (group
    ! input giPartType, 4 bits) and starts a cycle with diCycleStart. Each part type
    ! has its own program module on the controller disk, loaded when the type changes;
    ! its entry routine is called by late binding.

    RECORD PartProgram
        num code;
        string moduleFile;  ! file under PROG_DIR
        string entry;       ! entry routine of the module
    ENDRECORD

    CONST string PROG_DIR := "HOME:/Station30/";
    CONST num NUM_PROGRAMS := 4;
    CONST PartProgram programs{NUM_PROGRAMS} := [[1, "Housing.mod", "Housing:Cycle"],
        [2, "Cover.mod", "Cover:Cycle"], [3, "Arm3.mod", "Arm3:Cycle"],
        [4, "Bracket.mod", "Bracket:Cycle"]];

    ! Handshake codes on goCellState towards the PLC.
    CONST num STATE_IDLE := 0;
    CONST num STATE_BUSY := 1;
    CONST num STATE_DONE := 2;
    CONST num STATE_FAULT := 15;

    VAR num loadedIndex := 0;
    VAR clock cycleClock;
    VAR num partCode;
    VAR bool firstCycle := TRUE;
    PERS num lastPartCode := 0;

    PROC main()
        IF firstCycle THEN
            StartUp;
            firstCycle := FALSE;
        ENDIF
        waitStart:
        SetGO goCellState, STATE_IDLE;
        WaitDI diCycleStart, 1;
        partCode := GInput(giPartType);
        IF partCode = 0 THEN
            TPWrite "Start without part type: ignored";
            WaitDI diCycleStart, 0;
            GOTO waitStart;
        ENDIF
        SetGO goCellState, STATE_BUSY;
        ClkReset cycleClock;
        ClkStart cycleClock;
        RunPart partCode;
        ClkStop cycleClock;
        CycleDone ClkRead(cycleClock);
        SetGO goCellState, STATE_DONE;
        WaitDI diCycleStart, 0;
    ERROR (LONG_JMP_ALL_ERR)
        ! Any error not handled below main ends the cycle here: report it to the PLC
        ! and wait for a new start. The retry counter is not reset by a long jump.
        SetGO goCellState, STATE_FAULT;
        ErrWrite "Station 30", "Cycle aborted" \RL2:="error " + NumToStr(ERRNO, 0)
            \RL3:="part type " + NumToStr(partCode, 0);
        GoHome \Slow;
        WaitDI diFaultReset, 1;
        ResetRetryCount;
        TRYNEXT;
    ENDPROC

    PROC StartUp()
        TPErase;
        TPWrite "Station 30 starting, task " + GetTaskName();
        IF OpMode() = OP_MAN_PROG TPWrite "Manual mode: reduced speed";
        VelSet 100, 2500;
        AccSet 100, 100;
        GoHome \Slow;
        loadedIndex := 0;
    ENDPROC

    ! Loads the program module of a part type if it is not loaded, then runs it.
    PROC RunPart(num code)
        VAR num index;

        index := FindProgram(code);
        IF index = 0 THEN
            ErrWrite "Station 30", "No program for part type" \RL2:=NumToStr(code, 0);
            RETURN;
        ENDIF
        IF index <> loadedIndex THEN
            UnloadCurrent;
            Load \Dynamic, PROG_DIR \File:=programs{index}.moduleFile;
            loadedIndex := index;
            cellProgram := programs{index}.entry;
        ENDIF
        ! The entry is "module:routine", which late binding accepts; it takes the code.
        %programs{index}.entry% code;
        lastPartCode := code;
    ERROR
        TEST ERRNO
        CASE ERR_LOADED:
            ! Loaded already by someone else: just run it.
            loadedIndex := index;
            RETRY;
        CASE ERR_FILNOTFND:
            ErrWrite "Station 30", "Program file missing" \RL2:=programs{index}.moduleFile;
            RETURN;
        CASE ERR_REFUNKPRC, ERR_CALLPROC:
            ErrWrite "Station 30", "Entry routine not found" \RL2:=programs{index}.entry;
            RETURN;
        ENDTEST
        RAISE;
    ENDPROC

    PROC UnloadCurrent()
        IF loadedIndex = 0 RETURN;
        UnLoad PROG_DIR \File:=programs{loadedIndex}.moduleFile;
        loadedIndex := 0;
    ERROR
        IF ERRNO = ERR_UNLOAD THEN
            ! Not loaded any more: nothing to do.
            loadedIndex := 0;
            RETURN;
        ENDIF
        RAISE;
    ENDPROC

    FUNC num FindProgram(num code)
        FOR i FROM 1 TO NUM_PROGRAMS DO
            IF programs{i}.code = code RETURN i;
        ENDFOR
        RETURN 0;
    ENDFUNC

    ! Service routines called by number from the PLC service menu (CallByVar).
    PROC ServiceByNumber(num number)
        IF number < 1 OR number > 3 RETURN;
        CallByVar "Service", number;
    ERROR
        IF ERRNO = ERR_REFUNKPRC OR ERRNO = ERR_CALLPROC THEN
            TPWrite "No service routine number " \Num:=number;
            RETURN;
        ENDIF
        RAISE;
    ENDPROC

    PROC Service1()
        ! Gripper change position.
        MoveAbsJ jMaint \NoEOffs, vCellSlow, fine, tGripper;
    ENDPROC

    PROC Service2()
        ! TCP check on the reference needle.
        GoHome \Slow;
        MoveJ [[1500, 0, 900], [0, 0, 1, 0], [0, 0, 0, 0], [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]],
            vCellSlow, fine, tPointer;
        Stop;
        GoHome \Slow;
    ENDPROC

    PROC Service3()
        GoHome;
        UnloadCurrent;
    ENDPROC
ENDMODULE
