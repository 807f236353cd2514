MODULE socket_udp
! @format 3
! @section 13
! @expect ok
! @description UDP sockets (SocketCreate \UDP) on the loopback: SocketSendTo sends one datagram to an address and port, SocketReceiveFrom receives it with the sender's address and port; \Time bounds the wait (ERR_SOCK_TIMEOUT). The ports are the first free ones from 47300.
! @output datagram 8 from 127.0.0.1
! @output sender's port TRUE
! @output answer
! @output ERR_SOCK_TIMEOUT
! @exit 0
  VAR socketdev receiver;
  VAR socketdev sender;
  VAR num port := 47300;
  VAR num sender_port;
  VAR num from_port;
  VAR string text;
  VAR string origin;
  VAR num count;
  PROC main()
    SocketCreate receiver \UDP;
    WHILE NOT Bound(receiver, port) DO
      port := port + 1;
    ENDWHILE
    SocketCreate sender \UDP;
    sender_port := port + 1;
    WHILE NOT Bound(sender, sender_port) DO
      sender_port := sender_port + 1;
    ENDWHILE
    SocketSendTo sender, "127.0.0.1", port \Str:="datagram";
    SocketReceiveFrom receiver \Str:=text \NoRecBytes:=count, origin, from_port \Time:=5;
    TPWrite text + " " + ValToStr(count) + " from " + origin;
    TPWrite "sender's port " \Bool:=from_port = sender_port;
    SocketSendTo receiver, origin, from_port \Str:="answer";
    SocketReceiveFrom sender \Str:=text, origin, from_port \Time:=5;
    TPWrite text;
    SocketReceiveFrom sender \Str:=text, origin, from_port \Time:=0.2;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_SOCK_TIMEOUT THEN
      TPWrite "ERR_SOCK_TIMEOUT";
      SocketClose sender;
      SocketClose receiver;
      RETURN;
    ENDIF
  ENDPROC

  FUNC bool Bound(VAR socketdev s, num p)
    SocketBind s, "127.0.0.1", p;
    RETURN TRUE;
  ERROR
    IF ERRNO = ERR_SOCK_ADDR_INUSE RETURN FALSE;
  ENDFUNC
ENDMODULE
