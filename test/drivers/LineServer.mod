MODULE LineServer
    ! A line-protocol robot command server in the manner of the open_abb driver: our own,
    ! simplified version of its published format. A request is ASCII, "NN arg arg ... #": a
    ! numeric instruction code, blank-separated arguments, a closing "#". The reply is
    ! "NN ok value ... #" (or "NN error REASON #").
    !   00                         ping
    !   01 x y z q1 q2 q3 q4       linear move of tool0 to that pose in wobj0 (mm, quaternion)
    !   02 j1 j2 j3 j4 j5 j6       joint move to those axis angles (degrees)
    !   03                         the current pose: x y z q1 q2 q3 q4
    !   04                         the current joints: j1 .. j6
    !   99                         close this connection (the server accepts the next client)
    !   98                         close the connection and stop the server (ours, for the tests)
    ! The port is read from HOME:/line_server.cfg, so one module serves on any port.
    LOCAL VAR socketdev listener;
    LOCAL VAR socketdev client;
    LOCAL VAR num port;
    LOCAL VAR num args{10};
    LOCAL VAR num nargs;
    LOCAL VAR bool stop_server := FALSE;
    LOCAL VAR num sessions := 0;

    PROC main()
        ReadPort;
        SocketCreate listener;
        SocketBind listener, "127.0.0.1", port;
        SocketListen listener;
        TPWrite "line server listening";
        WHILE NOT stop_server DO
            SocketAccept listener, client \Time:=WAIT_MAX;
            Incr sessions;
            TPWrite "session " \Num:=sessions;
            Serve;
            SocketClose client;
        ENDWHILE
        SocketClose listener;
        TPWrite "line server stopped";
    ENDPROC

    LOCAL PROC ReadPort()
        VAR iodev cfg;
        Open "HOME:/line_server.cfg", cfg \Read;
        port := ReadNum(cfg);
        Close cfg;
    ENDPROC

    ! One client's session: requests until 99 or 98, or until the client goes away.
    LOCAL PROC Serve()
        VAR string request;
        VAR string reply;
        VAR num code;
        VAR bool done := FALSE;
        WHILE NOT done DO
            SocketReceive client \Str:=request \Time:=WAIT_MAX;
            IF Parse(request, code) THEN
                reply := Execute(code, done);
            ELSE
                reply := "-1 error syntax";
            ENDIF
            SocketSend client \Str:=reply + " #";
        ENDWHILE
    ERROR
        IF ERRNO = ERR_SOCK_CLOSED THEN
            TPWrite "client went away";
            RETURN;
        ENDIF
        RAISE;
    ENDPROC

    ! The code and the arguments of a request; FALSE when it is not "NN arg ... #".
    LOCAL FUNC bool Parse(string request, INOUT num code)
        VAR num len;
        VAR num start;
        VAR num stop;
        VAR string token;
        VAR bool closed := FALSE;
        VAR bool first := TRUE;
        len := StrLen(request);
        nargs := 0;
        start := StrFind(request, 1, STR_WHITE \NotInSet);
        WHILE start <= len AND (NOT closed) DO
            stop := StrFind(request, start, STR_WHITE);
            token := StrPart(request, start, stop - start);
            IF token = "#" THEN
                closed := TRUE;
            ELSEIF first THEN
                IF NOT StrToVal(token, code) RETURN FALSE;
                first := FALSE;
            ELSE
                IF nargs >= Dim(args, 1) RETURN FALSE;
                Incr nargs;
                IF NOT StrToVal(token, args{nargs}) RETURN FALSE;
            ENDIF
            IF stop > len THEN
                start := stop;
            ELSE
                start := StrFind(request, stop, STR_WHITE \NotInSet);
            ENDIF
        ENDWHILE
        RETURN closed AND (NOT first);
    ENDFUNC

    LOCAL FUNC string CodeText(num code)
        IF code >= 0 AND code < 10 RETURN "0" + NumToStr(code, 0);
        RETURN NumToStr(code, 0);
    ENDFUNC

    LOCAL FUNC string Execute(num code, INOUT bool done)
        VAR robtarget target;
        VAR jointtarget joints;
        VAR robtarget here;
        TEST code
        CASE 0:
            RETURN "00 ok";
        CASE 1:
            IF nargs <> 7 RETURN "01 error arguments";
            target := CRobT(\Tool:=tool0 \WObj:=wobj0);
            target.trans := [args{1}, args{2}, args{3}];
            target.rot := NOrient([args{4}, args{5}, args{6}, args{7}]);
            ConfL \Off;
            MoveL target, v500, fine, tool0 \WObj:=wobj0;
            RETURN "01 ok";
        CASE 2:
            IF nargs <> 6 RETURN "02 error arguments";
            joints := CJointT();
            joints.robax := [args{1}, args{2}, args{3}, args{4}, args{5}, args{6}];
            MoveAbsJ joints, v500, fine, tool0;
            RETURN "02 ok";
        CASE 3:
            here := CRobT(\Tool:=tool0 \WObj:=wobj0);
            RETURN "03 ok " + NumToStr(here.trans.x, 2) + " " + NumToStr(here.trans.y, 2) + " "
                + NumToStr(here.trans.z, 2) + " " + NumToStr(here.rot.q1, 4) + " " + NumToStr(here.rot.q2, 4)
                + " " + NumToStr(here.rot.q3, 4) + " " + NumToStr(here.rot.q4, 4);
        CASE 4:
            joints := CJointT();
            RETURN "04 ok " + NumToStr(joints.robax.rax_1, 2) + " " + NumToStr(joints.robax.rax_2, 2) + " "
                + NumToStr(joints.robax.rax_3, 2) + " " + NumToStr(joints.robax.rax_4, 2) + " "
                + NumToStr(joints.robax.rax_5, 2) + " " + NumToStr(joints.robax.rax_6, 2);
        CASE 99:
            done := TRUE;
            RETURN "99 ok";
        CASE 98:
            done := TRUE;
            stop_server := TRUE;
            RETURN "98 ok";
        DEFAULT:
            RETURN CodeText(code) + " error unknown";
        ENDTEST
    ERROR
        ! A move the robot cannot make: the client is told, the server goes on.
        RETURN CodeText(code) + " error " + NumToStr(ERRNO, 0);
    ENDFUNC
ENDMODULE
