MODULE Palletizer
    ! Palletising of cartons from an infeed conveyor onto two pallet stations.
    ! Layouts are data: each layer pattern is a list of box places in the pallet frame,
    ! odd and even layers may use different patterns (interlocking). A vacuum gripper
    ! picks one carton at a time; a failed pick is retried, a slot that cannot be
    ! reached is skipped and logged.

    RECORD BoxType
        string name;
        num length;         ! mm, along the pallet x axis when not turned
        num width;          ! mm
        num height;         ! mm
        num mass;           ! kg
    ENDRECORD

    RECORD BoxPlace
        num x;              ! mm, centre of the box in the pallet frame
        num y;
        num turn;           ! deg about z: 0 or 90
    ENDRECORD

    RECORD PalletState
        num layer;
        num place;
        num placed;
        bool full;
        ! the state survives a power failure: it is PERS
    ENDRECORD

    ALIAS num millimetre;

    CONST num MAX_PLACES := 8;
    CONST num MAX_LAYERS := 6;
    CONST num PICK_TRIES := 3;
    ! Approach height above the top of the stack, and above the pick point.
    CONST millimetre APPROACH := 150;
    CONST millimetre PICK_LIFT := 250;

    CONST BoxType box600x400 := ["600x400x250", 600, 400, 250, 11.5];

    ! Layer patterns for a 1200 x 800 pallet, five boxes, interlocked.
    CONST BoxPlace patternA{MAX_PLACES} := [[300, 200, 0], [900, 200, 0], [200, 600, 90],
        [600, 600, 90], [1000, 600, 90], [0, 0, -1], [0, 0, -1], [0, 0, -1]];
    CONST BoxPlace patternB{MAX_PLACES} := [[200, 200, 90], [600, 200, 90], [1000, 200, 90],
        [300, 600, 0], [900, 600, 0], [0, 0, -1], [0, 0, -1], [0, 0, -1]];

    PERS wobjdata wobjPallet1 := [FALSE, TRUE, "", [[1450, -950, 120], [0.707107, 0, 0, -0.707107]],
                                  [[0, 0, 0], [1, 0, 0, 0]]];
    PERS wobjdata wobjPallet2 := [FALSE, TRUE, "", [[1450, 950, 120], [0.707107, 0, 0, 0.707107]],
                                  [[0, 0, 0], [1, 0, 0, 0]]];
    PERS tooldata tVacuum := [TRUE, [[0, 0, 310], [1, 0, 0, 0]],
                              [14.2, [0, 0, 120], [1, 0, 0, 0], 0.25, 0.25, 0.1]];
    PERS loaddata loadBox := [11.5, [0, 0, 125], [1, 0, 0, 0], 0, 0, 0];

    PERS PalletState pallet1 := [1, 1, 0, FALSE];
    PERS PalletState pallet2 := [1, 1, 0, FALSE];
    PERS num totalPlaced := 0;

    CONST robtarget pPick := [[850, 0, 640], [0, 0, 1, 0], [0, 0, 0, 0],
                              [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]];
    ! Box centre at the pallet origin, tool pointing down.
    CONST robtarget pPlaceRef := [[0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 0],
                                  [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]];
    CONST robtarget pSheetPick := [[-300, 1150, 480], [0, 0.707107, 0.707107, 0], [1, 0, 1, 0],
                                   [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]];
    CONST jointtarget jSafe := [[0, -10, 10, 0, 90, 0], [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]];

    VAR errnum ERR_PAL_FULL := -1;
    VAR errnum ERR_NO_BOX := -1;
    VAR num pickTries := 0;
    VAR bool holding := FALSE;

    PROC main()
        PalInit;
        WHILE TRUE DO
            IF NOT holding PickBox;
            PlaceOnFreePallet;
        ENDWHILE
    ERROR
        ! Booked error numbers are variables: IF, not TEST (CASE needs constants).
        IF ERRNO = ERR_PAL_FULL THEN
            TPWrite "Both pallets full, waiting for exchange";
            WaitUntil DInput(diPallet1Empty) = 1 OR DInput(diPallet2Empty) = 1;
            ResetEmptied;
            RETRY;
        ELSEIF ERRNO = ERR_NO_BOX THEN
            TPWrite "Infeed empty";
            WaitDI diBoxAtPick, 1;
            RETRY;
        ELSEIF ERRNO = ERR_WAIT_MAXTIME THEN
            ErrWrite "Palletizer", "Vacuum not reached after retries"
                \RL2:="Check the suction cups, then press start";
            Stop;
            RETRY;
        ENDIF
    ENDPROC

    ! Chooses the first pallet that is not full; raises ERR_PAL_FULL when both are.
    PROC PlaceOnFreePallet()
        IF NOT pallet1.full THEN
            PlaceNext pallet1, wobjPallet1, box600x400;
        ELSEIF NOT pallet2.full THEN
            PlaceNext pallet2, wobjPallet2, box600x400;
        ELSE
            RAISE ERR_PAL_FULL;
        ENDIF
    ENDPROC

    PROC PalInit()
        BookErrNo ERR_PAL_FULL;
        BookErrNo ERR_NO_BOX;
        AccSet 70, 70;
        ConfJ \On;
        ConfL \Off;
        GripLoad load0;
        Reset doVacuum;
        Reset doBlowOff;
        Reset doSheetVacuum;
        holding := FALSE;
        MoveAbsJ jSafe \NoEOffs, v1000, fine, tVacuum;
    ENDPROC

    ! Picks one box at the infeed. The vacuum is given PICK_TRIES chances.
    PROC PickBox()
        VAR bool timedOut;

        pickTries := 0;
        IF DInput(diBoxAtPick) = 0 THEN
            WaitDI diBoxAtPick, 1 \MaxTime:=20 \TimeFlag:=timedOut;
            ! TimeFlag is TRUE when the wait timed out.
            IF timedOut RAISE ERR_NO_BOX;
        ENDIF
        MoveJ Offs(pPick, 0, 0, PICK_LIFT), v2000, z50, tVacuum;
        MoveL pPick, v500, fine, tVacuum;
        Set doVacuum;
        WaitDI diVacuumOk, 1 \MaxTime:=1.5;
        GripLoad loadBox;
        holding := TRUE;
        MoveL Offs(pPick, 0, 0, PICK_LIFT), v1000, z50, tVacuum;
    ERROR
        IF ERRNO = ERR_WAIT_MAXTIME AND pickTries < PICK_TRIES THEN
            ! Lift a little, go down again and wait for the vacuum once more.
            Incr pickTries;
            Reset doVacuum;
            MoveL Offs(pPick, 0, 0, 20), v100, fine, tVacuum;
            MoveL pPick, v50, fine, tVacuum;
            Set doVacuum;
            RETRY;
        ENDIF
        Reset doVacuum;
        RAISE;
    ENDPROC

    ! Places the gripped box on the next free place of a pallet and updates its state.
    PROC PlaceNext(INOUT PalletState state, PERS wobjdata pallet, BoxType box)
        VAR BoxPlace places{MAX_PLACES};
        VAR robtarget target;
        VAR num count;

        IF state.layer MOD 2 = 1 THEN
            places := patternA;
        ELSE
            places := patternB;
        ENDIF
        count := PlacesInPattern(places);
        target := PlaceTarget(places{state.place}, state.layer, box);
        MoveJ Offs(target, 0, 0, APPROACH + box.height), v2000, z50, tVacuum \WObj:=pallet;
        MoveL Offs(target, 0, 0, 30), v800, z5, tVacuum \WObj:=pallet;
        MoveL target, v200, fine, tVacuum \WObj:=pallet;
        Reset doVacuum;
        PulseDO \PLength:=0.3, doBlowOff;
        WaitTime 0.2;
        GripLoad load0;
        holding := FALSE;
        MoveL Offs(target, 0, 0, APPROACH), v1000, z50, tVacuum \WObj:=pallet;
        Advance state, count;
        IF state.place = 1 AND (NOT state.full) PlaceSlipSheet pallet, state.layer, box;
    ERROR
        IF ERRNO = ERR_ROBLIMIT OR ERRNO = ERR_OUTSIDE_REACH THEN
            ! The box stays in the gripper; main places it on the next place.
            ErrWrite \W, "Palletizer", "Place out of reach, skipped"
                \RL2:="layer " + NumToStr(state.layer, 0) + " place " + NumToStr(state.place, 0);
            ClearPath;
            Advance state, count;
            RETURN;
        ENDIF
        RAISE;
    ENDPROC

    ! Lays a slip sheet on a finished layer. A missing sheet is logged, not fatal.
    PROC PlaceSlipSheet(PERS wobjdata pallet, num layer, BoxType box)
        VAR robtarget sheetTarget;

        sheetTarget := Offs(pPlaceRef, 600, 400, (layer - 1) * box.height + 5);
        MoveJ Offs(pSheetPick, 0, 0, 200), v2000, z50, tVacuum;
        MoveL pSheetPick, v300, fine, tVacuum;
        Set doSheetVacuum;
        WaitDI diSheetGripped, 1 \MaxTime:=2;
        MoveL Offs(pSheetPick, 0, 0, 200), v1000, z50, tVacuum;
        MoveJ Offs(sheetTarget, 0, 0, APPROACH), v2000, z50, tVacuum \WObj:=pallet;
        MoveL sheetTarget, v300, fine, tVacuum \WObj:=pallet;
        Reset doSheetVacuum;
        MoveL Offs(sheetTarget, 0, 0, APPROACH), v1000, z50, tVacuum \WObj:=pallet;
    ERROR
        IF ERRNO = ERR_WAIT_MAXTIME THEN
            ErrWrite \I, "Palletizer", "No slip sheet gripped"
                \RL2:="layer " + NumToStr(layer, 0) + " stacked without sheet";
            Reset doSheetVacuum;
            TRYNEXT;
        ENDIF
        RAISE;
    ENDPROC

    ! Moves the state on to the next place, layer, or to full.
    PROC Advance(INOUT PalletState state, num count)
        Incr state.placed;
        Incr totalPlaced;
        IF state.place < count THEN
            Incr state.place;
        ELSEIF state.layer < MAX_LAYERS THEN
            Incr state.layer;
            state.place := 1;
        ELSE
            state.full := TRUE;
        ENDIF
    ENDPROC

    ! Number of places used by a pattern: entries with a negative turn are unused.
    FUNC num PlacesInPattern(BoxPlace places{*})
        VAR num n := 0;

        FOR i FROM 1 TO Dim(places, 1) DO
            IF places{i}.turn < 0 RETURN n;
            n := n + 1;
        ENDFOR
        RETURN n;
    ENDFUNC

    FUNC robtarget PlaceTarget(BoxPlace place, num layer, BoxType box)
        VAR robtarget target;

        target := Offs(pPlaceRef, place.x, place.y, layer * box.height);
        target.rot := OrientZYX(place.turn, 0, 180);
        RETURN target;
    ENDFUNC

    ! Total mass on a pallet, for the load check of the forklift station.
    FUNC num PalletMass(PalletState state, BoxType box)
        RETURN state.placed * box.mass;
    ENDFUNC

    PROC ResetEmptied()
        IF DInput(diPallet1Empty) = 1 pallet1 := [1, 1, 0, FALSE];
        IF DInput(diPallet2Empty) = 1 pallet2 := [1, 1, 0, FALSE];
    ENDPROC

    ! For the operator: layers completed on each pallet.
    PROC ShowStatus()
        TPErase;
        TPWrite "Pallet 1 layer " \Num:=pallet1.layer;
        TPWrite "Pallet 2 layer " \Num:=pallet2.layer;
        TPWrite "Boxes placed in total: " \Num:=totalPlaced;
        TPWrite "Mass on pallet 1 (kg): " \Num:=PalletMass(pallet1, box600x400);
    ENDPROC
ENDMODULE
