MODULE HandoverRob1
    ! MultiMove cell, task T_ROB1. ROB_1 picks a tube from the rack, finds its end by
    ! touch sensing, and hands it to ROB_2 (task T_ROB2), which holds it while both
    ! move together to the bending machine. The two tasks meet at WaitSyncTask points
    ! and move in coordination between SyncMoveOn and SyncMoveOff; every move of that
    ! section has an \ID that must match the one in T_ROB2.

    RECORD TubeInfo
        num serial;
        num length;         ! mm, measured by touch
        num diameter;       ! mm
        bool measured;
    ENDRECORD

    ! Both tasks declare these with the same names and values.
    PERS tasks taskList{2} := [["T_ROB1"], ["T_ROB2"]];
    VAR syncident syncStart;
    VAR syncident syncGrip;
    VAR syncident syncCoordOn;
    VAR syncident syncCoordOff;
    VAR syncident syncReleased;

    ! Shared with T_ROB2 (global PERS of the same name in both tasks).
    PERS TubeInfo handoverTube := [0, 0, 0, FALSE];
    PERS bool rob2Gripped := FALSE;

    ! Tube nominal length, and the search distance beyond it.
    CONST num TUBE_NOMINAL := 850;
    CONST num SEARCH_OVER := 40;
    CONST num SYNC_TIMEOUT := 60;

    PERS tooldata tTubeGrip := [TRUE, [[0, 0, 195], [1, 0, 0, 0]],
                                [3.2, [0, 0, 70], [1, 0, 0, 0], 0, 0, 0]];
    PERS loaddata loadTube := [2.9, [0, 0, 425], [1, 0, 0, 0], 0.17, 0.17, 0.001];
    ! Work object moved by ROB_2: coordinated motion is programmed in it.
    PERS wobjdata wobjRob2Grip := [FALSE, FALSE, "ROB_2", [[0, 0, 0], [1, 0, 0, 0]],
                                   [[0, 0, 250], [1, 0, 0, 0]]];

    CONST robtarget pRackAbove := [[420, -780, 900], [0, 0.707107, 0.707107, 0], [-1, 0, -1, 0],
                                   [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]];
    CONST robtarget pRackGrip := [[420, -780, 612], [0, 0.707107, 0.707107, 0], [-1, 0, -1, 0],
                                  [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]];
    CONST robtarget pTouchStart := [[900, -200, 750], [0.5, 0.5, 0.5, 0.5], [-1, 0, 0, 0],
                                    [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]];
    ! Handover and bending positions in the ROB_2 gripper frame.
    CONST robtarget pHandover := [[0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 0],
                                  [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]];
    CONST robtarget pBendLoad := [[0, 0, -120], [0, 1, 0, 0], [0, 0, 0, 0],
                                  [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]];
    CONST jointtarget jWait := [[-45, -20, 25, 0, 65, 0], [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]];

    VAR robtarget pTouched;
    VAR num tubeCount := 0;

    PROC main()
        MoveAbsJ jWait \NoEOffs, v1000, fine, tTubeGrip;
        WaitSyncTask syncStart, taskList \TimeOut:=SYNC_TIMEOUT;
        WHILE TRUE DO
            PickTube;
            MeasureTube;
            HandOver;
        ENDWHILE
    ERROR
        IF ERRNO = ERR_WAITSYNCTASK THEN
            TPWrite "T_ROB2 not ready, waiting again";
            RETRY;
        ENDIF
        RAISE;
    ENDPROC

    PROC PickTube()
        Incr tubeCount;
        MoveJ pRackAbove, v2000, z50, tTubeGrip;
        MoveL pRackGrip, v400, fine, tTubeGrip;
        SetDO doGrip1Close, 1;
        WaitDI diGrip1Closed, 1 \MaxTime:=2;
        GripLoad loadTube;
        MoveL pRackAbove, v800, z50, tTubeGrip;
        handoverTube := [tubeCount, 0, 25, FALSE];
    ENDPROC

    ! Touches the tube end on the sensor plate; the distance travelled gives the length.
    PROC MeasureTube()
        VAR robtarget searchEnd;

        MoveJ pTouchStart, v1000, fine, tTubeGrip;
        searchEnd := Offs(pTouchStart, 0, 0, -(SEARCH_OVER + 60));
        SearchL \Stop, diTouchPlate, pTouched, searchEnd, v50, tTubeGrip;
        handoverTube.length := TUBE_NOMINAL + (pTouchStart.trans.z - pTouched.trans.z) - 60;
        handoverTube.measured := TRUE;
        MoveL pTouchStart, v200, fine, tTubeGrip;
    ERROR
        IF ERRNO = ERR_WHLSEARCH THEN
            ! No contact within the search distance: tube too short or missing.
            ErrWrite \W, "Tube measure", "No contact with the touch plate"
                \RL2:="tube " + NumToStr(handoverTube.serial, 0);
            handoverTube.measured := FALSE;
            MoveL pTouchStart, v200, fine, tTubeGrip;
            RETURN;
        ELSEIF ERRNO = ERR_SIGSUPSEARCH THEN
            ! The plate signal was already high when the search started.
            WaitDI diTouchPlate, 0 \MaxTime:=5;
            RETRY;
        ENDIF
        RAISE;
    ENDPROC

    PROC HandOver()
        WaitSyncTask syncGrip, taskList;
        MoveL pHandover, v300, fine, tTubeGrip \WObj:=wobjRob2Grip;
        WaitUntil rob2Gripped \MaxTime:=5;
        SetDO doGrip1Close, 0;
        WaitDI diGrip1Closed, 0 \MaxTime:=2;
        GripLoad load0;
        SyncMoveOn syncCoordOn, taskList;
        MoveL Offs(pHandover, 0, 0, -150) \ID:=10, v200, z10, tTubeGrip \WObj:=wobjRob2Grip;
        MoveL pBendLoad \ID:=20, v200, fine, tTubeGrip \WObj:=wobjRob2Grip;
        SyncMoveOff syncCoordOff;
        WaitSyncTask syncReleased, taskList;
        MoveAbsJ jWait \NoEOffs, v1000, z50, tTubeGrip;
    ERROR
        IF ERRNO = ERR_WAIT_MAXTIME THEN
            ! ROB_2 did not grip: keep the tube and let the operator decide.
            IF IsSyncMoveOn() SyncMoveOff syncCoordOff;
            ErrWrite "Handover", "ROB_2 did not grip the tube";
            Stop;
            RETRY;
        ENDIF
        RAISE;
    UNDO
        IF IsSyncMoveOn() SyncMoveOff syncCoordOff;
    ENDPROC
ENDMODULE
