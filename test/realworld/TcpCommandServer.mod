MODULE TcpCommandServer
    ! A line-oriented TCP command server for a cell PC.
    ! The PC connects to port 1025 and sends one command per message, words separated by
    ! blanks, for example "MOVEL 120 -35.5 80" or "SETDO doClamp 1". Every command is
    ! answered with "OK ..." or "ERR ...". Moves are relative to wobjPcTable.

    LOCAL RECORD CmdWords
        num count;
        string w1;
        string w2;
        string w3;
        string w4;
        string w5;
        string w6;
        string w7;      ! words beyond the seventh are dropped
    ENDRECORD

    LOCAL CONST num SERVER_PORT := 1025;
    LOCAL CONST string SERVER_ADDRESS := "192.168.125.1";
    LOCAL CONST num MAX_WORDS := 7;
    LOCAL CONST num RECEIVE_TIMEOUT := 600;
    ! Raised by WordToNum for a word that is not a number.
    LOCAL CONST errnum CMD_ERR_NUMBER := 21;

    PERS wobjdata wobjPcTable := [FALSE, TRUE, "", [[800, -250, 420], [1, 0, 0, 0]],
                                [[0, 0, 0], [1, 0, 0, 0]]];
    PERS tooldata tProbe := [TRUE, [[0, 0, 156.5], [1, 0, 0, 0]],
                             [0.6, [0, 0, 40], [1, 0, 0, 0], 0, 0, 0]];

    LOCAL VAR socketdev listener;
    LOCAL VAR socketdev client;
    LOCAL VAR string request;
    LOCAL VAR string reply;
    LOCAL VAR CmdWords words;
    LOCAL VAR speeddata cmd_speed := [200, 100, 5000, 1000];
    LOCAL VAR signaldo cmd_output;
    LOCAL VAR bool quit_requested := FALSE;
    LOCAL VAR num commands_done := 0;

    PROC main()
        quit_requested := FALSE;
        OpenServer;
        WHILE NOT quit_requested DO
            SocketReceive client \Str:=request \Time:=RECEIVE_TIMEOUT;
            reply := Execute(request);
            SocketSend client \Str:=reply + "\0D\0A";
            Incr commands_done;
        ENDWHILE
        CloseServer;
        TPWrite "Command server stopped after commands: " \Num:=commands_done;
    ERROR
        TEST ERRNO
        CASE ERR_SOCK_TIMEOUT:
            TPWrite "No command for " \Num:=RECEIVE_TIMEOUT;
            RETRY;
        CASE ERR_SOCK_CLOSED:
            TPWrite "Client closed the connection";
            CloseServer;
            OpenServer;
            RETRY;
        DEFAULT:
            ErrWrite "Command server", "Unexpected error"
                \RL2:="ERRNO " + NumToStr(ERRNO, 0);
            CloseServer;
            RAISE;
        ENDTEST
    ENDPROC

    LOCAL PROC OpenServer()
        VAR string peer;

        SocketCreate listener;
        SocketBind listener, SERVER_ADDRESS, SERVER_PORT;
        SocketListen listener;
        SocketAccept listener, client \ClientAddress:=peer \Time:=WAIT_MAX;
        TPWrite "Command client: " + peer;
        SocketSend client \Str:="READY" + "\0D\0A";
    ENDPROC

    LOCAL PROC CloseServer()
        SocketClose client;
        SocketClose listener;
    ENDPROC

    ! Splits text into blank-separated words.
    LOCAL PROC SplitWords(string text, INOUT CmdWords result)
        VAR num pos := 1;
        VAR num wordEnd;
        VAR num len;
        VAR string word;

        result := [0, "", "", "", "", "", "", ""];
        len := StrLen(text);
        WHILE pos <= len AND result.count < MAX_WORDS DO
            ! Skip blanks, then take everything up to the next blank.
            pos := StrFind(text, pos, STR_WHITE \NotInSet);
            IF pos > len GOTO done;
            wordEnd := StrFind(text, pos, STR_WHITE);
            word := StrPart(text, pos, wordEnd - pos);
            Incr result.count;
            TEST result.count
            CASE 1:
                result.w1 := StrMap(word, STR_LOWER, STR_UPPER);
            CASE 2:
                result.w2 := word;
            CASE 3:
                result.w3 := word;
            CASE 4:
                result.w4 := word;
            CASE 5:
                result.w5 := word;
            CASE 6:
                result.w6 := word;
            DEFAULT:
                result.w7 := word;
            ENDTEST
            pos := wordEnd;
        ENDWHILE
        done:
    ENDPROC

    ! Converts word to a number; raises CMD_ERR_NUMBER when it is not one.
    LOCAL FUNC num WordToNum(string word)
        VAR num value;

        IF NOT StrToVal(word, value) RAISE CMD_ERR_NUMBER;
        RETURN value;
    ENDFUNC

    LOCAL FUNC string Execute(string text)
        VAR robtarget target;
        VAR jointtarget joints;
        VAR robtarget here;
        VAR num value;

        SplitWords text, words;
        IF words.count = 0 RETURN "ERR empty command";
        TEST words.w1
        CASE "PING":
            RETURN "OK PONG";
        CASE "GETPOS":
            here := CRobT(\Tool:=tProbe \WObj:=wobjPcTable);
            RETURN "OK " + NumToStr(here.trans.x, 2) + " " + NumToStr(here.trans.y, 2)
                + " " + NumToStr(here.trans.z, 2);
        CASE "GETJOINTS":
            joints := CJointT();
            RETURN "OK " + NumToStr(joints.robax.rax_1, 2) + " "
                + NumToStr(joints.robax.rax_2, 2) + " " + NumToStr(joints.robax.rax_3, 2);
        CASE "MOVEL", "MOVEJ":
            IF words.count < 4 RETURN "ERR " + words.w1 + " needs x y z";
            here := CRobT(\Tool:=tProbe \WObj:=wobjPcTable);
            target := here;
            target.trans := [WordToNum(words.w2), WordToNum(words.w3), WordToNum(words.w4)];
            IF words.w1 = "MOVEL" THEN
                MoveL target, cmd_speed, fine, tProbe \WObj:=wobjPcTable;
            ELSE
                MoveJ target, cmd_speed, fine, tProbe \WObj:=wobjPcTable;
            ENDIF
            RETURN "OK";
        CASE "SPEED":
            IF words.count < 2 RETURN "ERR SPEED needs a value";
            value := WordToNum(words.w2);
            IF value <= 0 OR value > 1000 RETURN "ERR speed out of range";
            cmd_speed.v_tcp := value;
            RETURN "OK";
        CASE "SETDO":
            IF words.count < 3 RETURN "ERR SETDO needs a signal and a value";
            value := WordToNum(words.w3);
            AliasIO words.w2, cmd_output;
            IF value = 0 THEN
                SetDO cmd_output, 0;
            ELSE
                SetDO cmd_output, 1;
            ENDIF
            RETURN "OK";
        CASE "QUIT":
            quit_requested := TRUE;
            RETURN "OK BYE";
        DEFAULT:
            RETURN "ERR unknown command " + words.w1;
        ENDTEST
    ERROR
        ! Every error of a command is answered; the server keeps running.
        IF ERRNO = CMD_ERR_NUMBER RETURN "ERR not a number";
        IF ERRNO = ERR_ALIASIO_DEF OR ERRNO = ERR_NO_ALIASIO_DEF RETURN "ERR unknown signal";
        IF ERRNO = ERR_STRTOOLNG RETURN "ERR reply too long";
        IF ERRNO = ERR_ROBLIMIT RETURN "ERR position out of reach";
        RETURN "ERR " + NumToStr(ERRNO, 0);
    ENDFUNC
ENDMODULE
