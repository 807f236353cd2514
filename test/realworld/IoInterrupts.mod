MODULE IoInterrupts
    ! Cell I/O and interrupts of a machine-tending cell: door and light curtain, part
    ! present sensors, a cyclic watchdog towards the PLC, an analog pressure monitor and
    ! an event-log interrupt. The signals of the cabinet are reached through AliasIO so
    ! the module runs on cells whose EIO names differ; the names are in one table.

    RECORD SignalMap
        string logical;     ! name used in this module
        string physical;    ! name in the EIO configuration
    ENDRECORD

    CONST SignalMap ioNames{6} := [["door", "DI10_1_DoorClosed"],
        ["curtain", "DI10_2_LightCurtain"], ["part", "DI10_5_PartPresent"],
        ["clamp", "DO10_1_Clamp"], ["lamp", "DO10_8_StackLight"],
        ["pressure", "AI12_1_AirPressure"]];

    ! Watchdog period towards the PLC, and the low air pressure limit (bar).
    CONST num WATCHDOG_PERIOD := 0.5;
    CONST num PRESSURE_LOW := 4.5;
    CONST num PRESSURE_HIGH := 8;

    VAR signaldi diDoor;
    VAR signaldi diCurtain;
    VAR signaldi diPart;
    VAR signaldo doClamp;
    VAR signaldo doLamp;
    VAR signalai aiPressure;

    VAR intnum intDoor;
    VAR intnum intCurtain;
    VAR intnum intWatchdog;
    VAR intnum intPressure;
    VAR intnum intErrLog;
    VAR intnum intPart;

    VAR bool doorOpened := FALSE;
    VAR bool partArrived := FALSE;
    VAR num watchdogCount := 0;
    VAR trapdata errTrapData;
    VAR errdomain lastDomain;
    VAR num lastErrNo;
    VAR errtype lastType;

    PERS bool ioConnected := FALSE;

    ! Maps the logical signals to the physical ones and connects every interrupt.
    PROC IoSetup()
        AliasIO ioNames{1}.physical, diDoor;
        AliasIO ioNames{2}.physical, diCurtain;
        AliasIO ioNames{3}.physical, diPart;
        AliasIO ioNames{4}.physical, doClamp;
        AliasIO ioNames{5}.physical, doLamp;
        AliasIO ioNames{6}.physical, aiPressure;
        IoConnectAll;
        ioConnected := TRUE;
    ERROR
        IF ERRNO = ERR_ALIASIO_DEF OR ERRNO = ERR_NO_ALIASIO_DEF THEN
            ErrWrite "IoInterrupts", "A cell signal is not configured"
                \RL2:="Check the EIO configuration";
            Stop;
        ENDIF
        RAISE;
    ENDPROC

    ! IDelete first: CONNECT may connect an intnum that is not connected yet only.
    PROC IoConnectAll()
        IoDisconnectAll;
        CONNECT intDoor WITH DoorTrap;
        ISignalDI diDoor, 0, intDoor;
        CONNECT intCurtain WITH SafetyTrap;
        ISignalDI \Single, diCurtain, 0, intCurtain;
        CONNECT intPart WITH PartTrap;
        ISignalDI diPart, 1, intPart;
        CONNECT intWatchdog WITH WatchdogTrap;
        ITimer WATCHDOG_PERIOD, intWatchdog;
        CONNECT intPressure WITH PressureTrap;
        ISignalAI aiPressure, AIO_OUTSIDE, PRESSURE_HIGH, PRESSURE_LOW, 0, intPressure;
        CONNECT intErrLog WITH ErrLogTrap;
        IError COMMON_ERR, TYPE_ALL, intErrLog;
    ENDPROC

    PROC IoDisconnectAll()
        IDelete intDoor;
        IDelete intCurtain;
        IDelete intPart;
        IDelete intWatchdog;
        IDelete intPressure;
        IDelete intErrLog;
        ioConnected := FALSE;
    ENDPROC

    ! Clamps the part in the machine vice and checks the clamp answers.
    PROC ClampPart()
        partArrived := FALSE;
        WaitUntil partArrived OR TestDI(diPart) \MaxTime:=30;
        SetDO \SDelay:=0.2, doClamp, 1;
        WaitDO doClamp, 1;
        WaitTime \InPos, 0.5;
        WaitDI diClampClosed, 1 \MaxTime:=3;
    ERROR
        IF ERRNO = ERR_WAIT_MAXTIME THEN
            ErrWrite \W, "Clamp", "No part or clamp not closed";
            SetDO doClamp, 0;
            Stop;
            RETRY;
        ENDIF
        RAISE;
    ENDPROC

    PROC UnclampPart()
        SetDO doClamp, 0;
        WaitDI diClampClosed, 0 \MaxTime:=3;
        PulseDO \High \PLength:=1, doLamp;
    ENDPROC

    ! Interrupts stay queued while a critical sequence runs.
    PROC CriticalSequence()
        IDisable;
        SetDO doClamp, 1;
        WaitTime 0.1;
        SetDO doClamp, 0;
        IEnable;
    ERROR
        IEnable;
        RAISE;
    UNDO
        IEnable;
    ENDPROC

    ! The watchdog is silenced while the controller is in manual mode.
    PROC WatchdogPause(\switch Resume)
        IF Present(Resume) THEN
            IWatch intWatchdog;
        ELSE
            ISleep intWatchdog;
        ENDIF
    ENDPROC

    FUNC bool CellIsSafe()
        RETURN TestDI(diDoor) AND TestDI(diCurtain) AND (NOT doorOpened);
    ENDFUNC

    TRAP DoorTrap
        doorOpened := TRUE;
        StopMove;
        TPWrite "Door opened: motion held";
        SetDO doLamp, 1;
        WaitDI diDoor, 1;
        doorOpened := FALSE;
        SetDO doLamp, 0;
        StartMove;
    ENDTRAP

    ! A single interrupt: the light curtain stops the robot on its path, keeps the path
    ! and waits for the curtain to close. IoConnectAll orders it again at the next cycle.
    TRAP SafetyTrap
        StopMove;
        StorePath;
        TPWrite "Light curtain broken";
        WaitDI diCurtain, 1;
        RestoPath;
        StartMove;
    ENDTRAP

    TRAP PartTrap
        partArrived := TRUE;
    ENDTRAP

    TRAP WatchdogTrap
        Incr watchdogCount;
        IF watchdogCount >= 1000 watchdogCount := 0;
        InvertDO doPlcWatchdog;
    ENDTRAP

    ! One trap for the pressure monitor and for any other interrupt it may get later.
    TRAP PressureTrap
        VAR num pressure;

        pressure := AInput(aiPressure);
        IF INTNO = intPressure THEN
            IF pressure < PRESSURE_LOW THEN
                ErrWrite \W, "Air pressure low", NumToStr(pressure, 1) + " bar";
                SetDO doLamp, 1;
            ELSE
                ErrWrite \W, "Air pressure high", NumToStr(pressure, 1) + " bar";
            ENDIF
        ELSE
            TPWrite "Unexpected interrupt " \Num:=INTNO;
        ENDIF
    ENDTRAP

    TRAP ErrLogTrap
        GetTrapData errTrapData;
        ReadErrData errTrapData, lastDomain, lastErrNo, lastType;
        IF lastType = TYPE_ERR THEN
            SetDO doLamp, 1;
            TPWrite "Controller error, domain " \Num:=lastDomain;
        ENDIF
    ENDTRAP
ENDMODULE
