MODULE socket_wait_a
! @format 4
! @task T_ROB1
! @section 14
! @section 13
! @expect ok
! @description While one task waits in a blocking socket call, the other tasks go on on the one clock (R-14-n): T_ROB1 waits 0.5 s in SocketReceive for data that never comes, and T_B, which waits 0.2 s, writes in the meantime, at 0.2 s on its clock (not when the receive has ended); the receive then times out with ERR_SOCK_TIMEOUT. T_ROB1 connects to a server socket of its own, which accepts the connection and never sends; its port is the first free one from 47472 (test runs may overlap).
! @output B after 0.2
! @output A ERR_SOCK_TIMEOUT
  VAR socketdev server;
  VAR socketdev client;
  VAR socketdev peer;
  VAR string text;
  VAR num port := 47472;
  PROC main()
    SocketCreate server;
    WHILE NOT Bound(port) DO
      port := port + 1;
    ENDWHILE
    SocketListen server;
    SocketCreate client;
    SocketConnect client, "127.0.0.1", port;
    SocketAccept server, peer;
    SocketReceive client \Str := text \Time := 0.5;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_SOCK_TIMEOUT THEN
      TPWrite "A ERR_SOCK_TIMEOUT";
      SocketClose peer;
      SocketClose client;
      SocketClose server;
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
