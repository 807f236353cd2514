MODULE socket_wait_interrupt
! @format 3
! @section 13
! @section 8
! @expect ok
! @description A blocking socket call is a waiting instruction: an interrupt that occurs while SocketAccept waits for a client is served then, at any time during the wait (§8), not after the call (R-14-n). The timer's trap runs 0.1 s into the accept's wait of 0.5 s; the accept then times out with ERR_SOCK_TIMEOUT, its \Time measured on the virtual clock.
! @output trap at 0.1
! @output ERR_SOCK_TIMEOUT at 0.5
! @exit 0
  VAR socketdev server;
  VAR socketdev client;
  VAR intnum tick;
  VAR clock c;
  PROC main()
    SocketCreate server;
    SocketBind server, "127.0.0.1", 47471;
    SocketListen server;
    CONNECT tick WITH on_tick;
    ClkStart c;
    ITimer \Single, 0.1, tick;
    SocketAccept server, client \Time := 0.5;
    TPWrite "not reached";
  ERROR
    IF ERRNO = ERR_SOCK_TIMEOUT THEN
      TPWrite "ERR_SOCK_TIMEOUT at " \Num := Round(ClkRead(c) \Dec := 1);
      SocketClose server;
      RETURN;
    ENDIF
  ENDPROC
  TRAP on_tick
    TPWrite "trap at " \Num := Round(ClkRead(c) \Dec := 1);
  ENDTRAP
ENDMODULE
