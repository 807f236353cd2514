MODULE sig_sockets
! @format 2
! @section 13
! @section 4.6
! @expect ok
! @description The socket routines as ABB documents them (SocketCreate \UDP, SocketConnect \Time, SocketBind, SocketListen, SocketAccept \ClientAddress \Time, SocketSend \Str | \RawData | \Data \NoOfBytes, SocketReceive with \ReadNoOfBytes \NoRecBytes \Time, SocketSendTo, SocketReceiveFrom, SocketPeek, SocketGetStatus, SocketClose), socketstatus, the raw-data routines and the socket errors.
  VAR socketdev server;
  VAR socketdev client;
  VAR socketdev udp;
  VAR rawbytes raw;
  VAR rawbytes copy;
  VAR byte data{4};
  VAR string text;
  VAR string peer;
  VAR num port;
  VAR num got;
  VAR num joint := 12.5;
  PROC main()
    SocketCreate server;
    SocketBind server, "192.168.125.1", 1025;
    SocketListen server;
    SocketAccept server, client \ClientAddress:=peer \Time:=WAIT_MAX;
    SocketReceive client \Str:=text \ReadNoOfBytes:=10 \NoRecBytes:=got \Time:=5;
    SocketReceive client \RawData:=raw;
    SocketReceive client \Data:=data;
    ClearRawBytes raw;
    PackRawBytes joint, raw \Network, 1 \Float4;
    PackRawBytes 7, raw, RawBytesLen(raw) + 1 \IntX:=DINT;
    PackRawBytes "ok", raw, RawBytesLen(raw) + 1 \ASCII;
    CopyRawBytes raw, 1, copy, 1 \NoOfBytes:=4;
    UnpackRawBytes copy \Network, 1, joint \Float4;
    UnpackRawBytes copy, 5, text \ASCII:=2;
    SocketSend client \Str:="hello";
    SocketSend client \RawData:=raw \NoOfBytes:=8;
    SocketSend client \Data:=data;
    got := SocketPeek(client);
    IF SocketGetStatus(client) = SOCKET_CONNECTED SocketClose client;
    SocketCreate udp \UDP;
    SocketSendTo udp, "192.168.125.2", 5000 \Str:="ping";
    SocketReceiveFrom udp \Str:=text, peer, port \Time:=1;
    SocketClose udp;
    SocketCreate client;
    SocketConnect client, "192.168.125.2", 5001 \Time:=2;
  ERROR
    IF ERRNO = ERR_SOCK_TIMEOUT THEN
      RETRY;
    ELSEIF ERRNO = ERR_SOCK_CLOSED THEN
      RETURN;
    ENDIF
  ENDPROC
ENDMODULE
