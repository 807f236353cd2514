MODULE socket_tcp
! @format 3
! @section 13
! @expect ok
! @description A TCP server and client in one task on the loopback: SocketCreate, SocketBind, SocketListen, SocketConnect (the connection waits in the listener's queue), SocketAccept, SocketSend and SocketReceive with \Str, \RawData and \Data, \NoOfBytes, \ReadNoOfBytes and \NoRecBytes, SocketPeek, SocketGetStatus in every state, and ERR_SOCK_TIMEOUT when nothing comes within \Time. The port is the first free one from 47200.
! @output never created 5
! @output created 1
! @output bound 3
! @output listening 4
! @output connected 2
! @output from 127.0.0.1
! @output first five: hello
! @output waiting 7
! @output rest:  server (7)
! @output raw 513
! @output data [1,2,3,250]
! @output cut abc
! @output ERR_SOCK_TIMEOUT
! @output closed 5
! @exit 0
  VAR socketdev server;
  VAR socketdev client;
  VAR socketdev peer;
  VAR num port := 47200;
  VAR string text;
  VAR string address;
  VAR rawbytes raw;
  VAR rawbytes got;
  VAR num bytes{4} := [1, 2, 3, 250];
  VAR num received{4};
  VAR num count;
  PROC main()
    TPWrite "never created " \Num:=SocketGetStatus(server);
    SocketCreate server;
    TPWrite "created " \Num:=SocketGetStatus(server);
    WHILE NOT Bound(port) DO
      port := port + 1;
    ENDWHILE
    TPWrite "bound " \Num:=SocketGetStatus(server);
    SocketListen server;
    TPWrite "listening " \Num:=SocketGetStatus(server);
    SocketCreate client;
    SocketConnect client, "127.0.0.1", port \Time:=5;
    SocketAccept server, peer \ClientAddress:=address \Time:=5;
    TPWrite "connected " \Num:=SocketGetStatus(client);
    TPWrite "from " + address;
    SocketSend client \Str:="hello server";
    SocketReceive peer \Str:=text \ReadNoOfBytes:=5 \Time:=5;
    TPWrite "first five: " + text;
    TPWrite "waiting " \Num:=SocketPeek(peer);
    SocketReceive peer \Str:=text \NoRecBytes:=count \Time:=5;
    TPWrite "rest: " + text + " (" + ValToStr(count) + ")";
    PackRawBytes 513, raw, 1 \IntX:=INT;
    SocketSend peer \RawData:=raw;
    SocketReceive client \RawData:=got \ReadNoOfBytes:=2 \Time:=5;
    UnpackRawBytes got, 1, count \IntX:=INT;
    TPWrite "raw " \Num:=count;
    SocketSend peer \Data:=bytes \NoOfBytes:=4;
    SocketReceive client \Data:=received \ReadNoOfBytes:=4 \Time:=5;
    TPWrite "data " + ValToStr(received);
    SocketSend client \Str:="abcdef" \NoOfBytes:=3;
    SocketReceive peer \Str:=text \ReadNoOfBytes:=3 \Time:=5;
    TPWrite "cut " + text;
    SocketReceive peer \Str:=text \Time:=0.2;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_SOCK_TIMEOUT THEN
      TPWrite "ERR_SOCK_TIMEOUT";
      SocketClose client;
      SocketClose peer;
      SocketClose server;
      TPWrite "closed " \Num:=SocketGetStatus(server);
      RETURN;
    ENDIF
  ENDPROC

  ! Binds the server to the port, or FALSE when another program holds it.
  FUNC bool Bound(num p)
    SocketBind server, "127.0.0.1", p;
    RETURN TRUE;
  ERROR
    IF ERRNO = ERR_SOCK_ADDR_INUSE RETURN FALSE;
  ENDFUNC
ENDMODULE
