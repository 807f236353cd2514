MODULE CommandServer
    ! A line-oriented TCP command server, in the style of the public drivers: the client
    ! connects, gets READY, sends one command per message ("PING", "ADD a b", "QUIT") and gets
    ! one answer per command. The port is the test's: it writes it into SERVER_PORT.
    LOCAL CONST string SERVER_ADDRESS := "192.168.125.1";
    LOCAL CONST num SERVER_PORT := @PORT@;
    LOCAL VAR socketdev listener;
    LOCAL VAR socketdev client;
    LOCAL VAR string request;
    LOCAL VAR string reply;
    LOCAL VAR bool quit_requested := FALSE;
    LOCAL VAR num commands_done := 0;

    PROC main()
        VAR string peer;
        SocketCreate listener;
        SocketBind listener, SERVER_ADDRESS, SERVER_PORT;
        SocketListen listener;
        SocketAccept listener, client \ClientAddress:=peer \Time:=20;
        TPWrite "Command client: " + peer;
        SocketSend client \Str:="READY" + "\0D\0A";
        WHILE NOT quit_requested DO
            SocketReceive client \Str:=request \Time:=20;
            reply := Execute(request);
            SocketSend client \Str:=reply + "\0D\0A";
            Incr commands_done;
        ENDWHILE
        SocketClose client;
        SocketClose listener;
        TPWrite "Status after close: " \Num:=SocketGetStatus(client);
        TPWrite "Command server stopped after commands: " \Num:=commands_done;
    ERROR
        TEST ERRNO
        CASE ERR_SOCK_TIMEOUT:
            TPWrite "Timeout";
        CASE ERR_SOCK_CLOSED:
            TPWrite "Client closed the connection";
        DEFAULT:
            TPWrite "Error " \Num:=ERRNO;
        ENDTEST
        SocketClose client;
        SocketClose listener;
    ENDPROC

    LOCAL FUNC string Execute(string command)
        VAR num blank;
        VAR num second;
        VAR num a;
        VAR num b;
        VAR string rest;
        IF command = "PING" RETURN "PONG";
        IF command = "QUIT" THEN
            quit_requested := TRUE;
            RETURN "BYE";
        ENDIF
        IF StrPart(command, 1, 3) = "ADD" THEN
            rest := StrPart(command, 5, StrLen(command) - 4);
            blank := StrFind(rest, 1, " ");
            IF StrToVal(StrPart(rest, 1, blank - 1), a)
                AND StrToVal(StrPart(rest, blank + 1, StrLen(rest) - blank), b) THEN
                RETURN "OK " + NumToStr(a + b, 0);
            ENDIF
        ENDIF
        RETURN "ERR unknown command";
    ENDFUNC
ENDMODULE
