MODULE OperatorUi
    ! Operator dialogues on the FlexPendant and error logging for a test rig
    ! (Prüfstand 7, Werk Süd).
    ! Older menus use TPReadFK and TPReadNum; the newer ones the UI instructions.
    ! Every error the operator acknowledges is also written to the event log.

    RECORD MenuEntry
        string text;
        string routine;     ! called by late binding
        bool needsAuto;     ! only in automatic mode
    ENDRECORD

    CONST num MENU_SIZE := 5;
    CONST MenuEntry menu{MENU_SIZE} := [["Run production", "RigProduction", TRUE],
        ["Single test cycle", "RigSingleCycle", FALSE], ["Go to service position", "RigService", FALSE],
        ["Calibrate load cell", "RigCalibrate", FALSE], ["Show statistics", "RigStatistics", FALSE]];

    ! Event log numbers for ErrLog: 4800..4999 are free for user messages.
    CONST num ELOG_OPERATOR := 4810;
    CONST num ELOG_LIMIT := 4811;

    VAR listitem menuItems{MENU_SIZE};
    VAR btnres answer;
    VAR num fkAnswer;
    VAR num testForce := 250;
    VAR errnum fkBreak;
    VAR string limitText{3};
    PERS num rigCycles := 0;
    PERS num rigFailures := 0;

    PROC main()
        VAR num choice;

        TPErase;
        TPWrite "Test rig 7 - RAPID " + RobOS_Text();
        TPWrite "Cycles: " \Num:=rigCycles;
        TPWrite "Failures: " \Num:=rigFailures;
        WHILE TRUE DO
            choice := ShowMenu();
            IF choice >= 1 AND choice <= MENU_SIZE THEN
                RunEntry menu{choice};
            ENDIF
        ENDWHILE
    ENDPROC

    LOCAL FUNC string RobOS_Text()
        IF RobOS() RETURN "controller";
        RETURN "virtual controller";
    ENDFUNC

    ! Shows the menu as a list and returns the chosen index, or 0.
    FUNC num ShowMenu()
        VAR num selected;

        FOR i FROM 1 TO MENU_SIZE DO
            menuItems{i}.image := "";
            menuItems{i}.text := menu{i}.text;
        ENDFOR
        selected := UIListView(\Result:=answer \Header:="Test rig 7", menuItems
            \Buttons:=btnOKCancel \Icon:=iconInfo \DefaultIndex:=1);
        IF answer <> resOK RETURN 0;
        RETURN selected;
    ENDFUNC

    PROC RunEntry(MenuEntry entry)
        IF entry.needsAuto AND OpMode() <> OP_AUTO THEN
            UIMsgBox \Header:="Not allowed", """" + entry.text + """ needs automatic mode"
                \MsgLine2:="Switch the key to AUTO and try again" \Buttons:=btnOK
                \Icon:=iconWarning;
            RETURN;
        ENDIF
        %entry.routine%;
    ERROR
        IF ERRNO = ERR_REFUNKPRC OR ERRNO = ERR_CALLPROC THEN
            ReportError "Menu entry has no routine", entry.routine;
            RETURN;
        ENDIF
        RAISE;
    ENDPROC

    ! Asks for the test force; keeps the old value when the operator cancels.
    PROC AskTestForce()
        VAR num value;

        value := UINumEntry(\Header:="Test force" \Message:="Force in N (50 - 900)"
            \Icon:=iconInfo \InitValue:=testForce \MinValue:=50 \MaxValue:=900
            \AsInteger \MaxTime:=60);
        testForce := value;
    ERROR
        IF ERRNO = ERR_TP_MAXTIME THEN
            TPWrite "No answer, force stays " \Num:=testForce;
            RETURN;
        ENDIF
        RAISE;
    ENDPROC

    ! The classic way: function keys.
    FUNC bool ConfirmFK(string question)
        TPReadFK fkAnswer, question, "Yes", stEmpty, stEmpty, stEmpty, "No"
            \MaxTime:=30 \BreakFlag:=fkBreak;
        ! BreakFlag holds the error the wait ended with, if any.
        IF fkBreak = ERR_TP_MAXTIME RETURN FALSE;
        RETURN fkAnswer = 1;
    ENDFUNC

    ! Asks for a number with TPReadNum until it lies in [low, high].
    FUNC num ReadNumberIn(string prompt, num low, num high)
        VAR num value;

        TPReadNum value, prompt;
        WHILE value < low OR value > high DO
            TPWrite "Out of range: " \Num:=value;
            TPWrite "Allowed from " + NumToStr(low, 0) + " to " + NumToStr(high, 0);
            TPReadNum value, prompt;
        ENDWHILE
        RETURN value;
    ENDFUNC

    ! A test result out of limits: the operator decides whether to go on.
    PROC LimitExceeded(string what, num measured, num limit)
        Incr rigFailures;
        ErrLog ELOG_LIMIT \W, what, NumToStr(measured, 2), NumToStr(limit, 2), GetTaskName(), CTime();
        limitText{1} := "Measured " + what;
        limitText{2} := NumToStr(measured, 2) + " > " + NumToStr(limit, 2);
        limitText{3} := "Continue the test?";
        answer := UIMessageBox(\Header:="Limit exceeded" \MsgArray:=limitText
            \Buttons:=btnYesNo \Icon:=iconError);
        IF answer = resNo THEN
            ErrWrite \W, "Test aborted by operator", what;
            Stop;
        ENDIF
    ENDPROC

    ! Writes an error to the event log and to the FlexPendant.
    PROC ReportError(string header, string reason \string Detail \switch Fatal)
        IF Present(Detail) THEN
            ErrWrite header, reason \RL2:=Detail;
        ELSE
            ErrWrite header, reason;
        ENDIF
        TPWrite header + ": " + reason;
        ErrLog ELOG_OPERATOR \I, header, reason, GetTaskName(), CDate(), CTime();
        IF Present(Fatal) THEN
            UIMsgBox \Header:=header, reason \MsgLine2:="The program stops." \Buttons:=btnOK
                \Icon:=iconError;
            EXIT;
        ENDIF
    ENDPROC

    ! Menu entries. RigCalibrate is in the calibration module, loaded on demand; until
    ! it is loaded, its menu entry reports the missing routine.
    PROC RigProduction()
        WHILE ConfirmFK("Run another cycle?") DO
            RigSingleCycle;
        ENDWHILE
    ENDPROC

    PROC RigSingleCycle()
        VAR num measured;

        AskTestForce;
        measured := ReadNumberIn("Measured deflection (mm)?", 0, 50);
        Incr rigCycles;
        IF measured > testForce / 100 LimitExceeded "deflection", measured, testForce / 100;
    ENDPROC

    PROC RigService()
        IF NOT ConfirmFK("Move to the service position?") RETURN;
        MoveAbsJ [[90, 0, 0, 0, 30, 0], [9E+09, 9E+09, 9E+09, 9E+09, 9E+09, 9E+09]] \NoEOffs,
            v500, fine, tool0;
    ENDPROC

    PROC RigStatistics()
        VAR num rate := 0;

        IF rigCycles > 0 rate := rigFailures / rigCycles * 100;
        TPErase;
        TPWrite "Cycles:   " \Num:=rigCycles;
        TPWrite "Failures: " \Num:=rigFailures;
        TPWrite "Rate (%): " \Num:=Round(rate \Dec:=1);
        IF ConfirmFK("Reset statistics?") THEN
            rigCycles := 0;
            rigFailures := 0;
        ENDIF
    ENDPROC
ENDMODULE
