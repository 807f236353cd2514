MODULE client
  VAR socketdev sock;
  VAR string reply := "none";
  VAR num status := 7;
  PROC main()
    SocketCreate sock;
    SocketConnect sock, "192.168.0.10", 1025;
    SocketReceive sock \Str:=reply;
    TPWrite "reply: " + reply;
    status := SocketGetStatus(sock);
    TPWrite "status: " \Num:=status;
    IF IsFile("HOME:/log.txt") THEN
      TPWrite "a log";
    ELSE
      TPWrite "no log";
    ENDIF
    SocketClose sock;
    SocketClose sock;
    TPWrite "done";
  ENDPROC
ENDMODULE
