MODULE socket_errors
! @format 3
! @section 13
! @expect ok
! @description The socket errors: an address that is not a dotted address or not reachable by default (not the loopback) ERR_SOCK_ADDR_INVALID, a socket never created or closed ERR_SOCK_CLOSED, SocketListen before SocketBind ERR_SOCK_NOT_BOUND, a second SocketBind ERR_SOCK_IS_BOUND, SocketSend on a socket not connected ERR_SOCK_NOT_CONN, a port nobody listens on ERR_SOCK_CLOSED, and SocketReceive after the peer closed ERR_SOCK_CLOSED.
! @output 1 ERR_SOCK_CLOSED
! @output 2 ERR_SOCK_ADDR_INVALID
! @output 3 ERR_SOCK_ADDR_INVALID
! @output 4 ERR_SOCK_ADDR_INVALID
! @output 5 ERR_SOCK_NOT_BOUND
! @output 6 ERR_SOCK_NOT_CONN
! @output 7 ERR_SOCK_IS_BOUND
! @output 8 ERR_SOCK_CLOSED
! @output 9 ERR_SOCK_CLOSED
! @output 10 ERR_SOCK_CLOSED
! @exit 0
  VAR socketdev s;
  VAR socketdev t;
  VAR socketdev server;
  VAR socketdev peer;
  VAR num port := 47400;
  VAR string text;
  PROC main()
    TPWrite "1 " + Attempt(1);
    TPWrite "2 " + Attempt(2);
    TPWrite "3 " + Attempt(3);
    TPWrite "4 " + Attempt(4);
    TPWrite "5 " + Attempt(5);
    TPWrite "6 " + Attempt(6);
    TPWrite "7 " + Attempt(7);
    TPWrite "8 " + Attempt(8);
    TPWrite "9 " + Attempt(9);
    TPWrite "10 " + Attempt(10);
  ENDPROC

  FUNC string Attempt(num what)
    TEST what
    CASE 1:
      SocketSend s \Str:="never created";
    CASE 2:
      SocketCreate s;
      SocketBind s, "localhost.example", 47400;
    CASE 3:
      SocketBind s, "10.1.2.3", 47400;
    CASE 4:
      SocketConnect s, "192.168.125.1", 1025 \Time:=1;
    CASE 5:
      SocketListen s;
    CASE 6:
      SocketSend s \Str:="not connected";
    CASE 7:
      SocketCreate server;
      WHILE NOT Bound(port) DO
        port := port + 1;
      ENDWHILE
      SocketBind server, "127.0.0.1", port;
    CASE 8:
      SocketClose server;
      SocketConnect s, "127.0.0.1", port \Time:=2;
    CASE 9:
      SocketClose s;
      SocketCreate server;
      WHILE NOT Bound(port) DO
        port := port + 1;
      ENDWHILE
      SocketListen server;
      SocketCreate t;
      SocketConnect t, "127.0.0.1", port \Time:=2;
      SocketAccept server, peer \Time:=2;
      SocketClose t;
      SocketReceive peer \Str:=text \Time:=2;
    CASE 10:
      SocketClose peer;
      SocketClose server;
      SocketSend peer \Str:="closed";
    ENDTEST
    RETURN "no error";
  ERROR
    TEST ERRNO
    CASE ERR_SOCK_ADDR_INVALID: RETURN "ERR_SOCK_ADDR_INVALID";
    CASE ERR_SOCK_CLOSED: RETURN "ERR_SOCK_CLOSED";
    CASE ERR_SOCK_NOT_BOUND: RETURN "ERR_SOCK_NOT_BOUND";
    CASE ERR_SOCK_IS_BOUND: RETURN "ERR_SOCK_IS_BOUND";
    CASE ERR_SOCK_NOT_CONN: RETURN "ERR_SOCK_NOT_CONN";
    CASE ERR_SOCK_TIMEOUT: RETURN "ERR_SOCK_TIMEOUT";
    DEFAULT: RETURN "other " + ValToStr(ERRNO);
    ENDTEST
  ENDFUNC

  FUNC bool Bound(num p)
    SocketBind server, "127.0.0.1", p;
    RETURN TRUE;
  ERROR
    IF ERRNO = ERR_SOCK_ADDR_INUSE RETURN FALSE;
  ENDFUNC
ENDMODULE
