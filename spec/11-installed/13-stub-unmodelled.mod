MODULE stub_unmodelled
! @format 3
! @section 13
! @section 2.22
! @options stub-unmodelled
! @expect ok
! @description Under rapid-sem's --stub-unmodelled (doc/rulings.md R-13-i) an installed routine it does not model runs as a no-op: a procedure does nothing and leaves its VAR and INOUT arguments as they were (reply keeps its value), a function returns the initial value of its result type (§2.22: 0 for SocketGetStatus's socketstatus, FALSE for IsFile, "" for ReadStr), and the run goes on to its end (exit 0). Each routine is called twice; nothing else changes.
! @output reply: none
! @output status: 0
! @output no file
! @output line: ""
! @output reply: none
! @output done
! @exit 0
  VAR socketdev client;
  VAR iodev log;
  VAR string reply := "none";
  VAR num status := 7;
  PROC main()
    FOR i FROM 1 TO 2 DO
      SocketCreate client;
      SocketReceive client \Str:=reply;
      TPWrite "reply: " + reply;
      IF i = 1 THEN
        status := SocketGetStatus(client);
        TPWrite "status: " \Num:=status;
        IF IsFile("HOME:/log.txt") THEN
          TPWrite "a file";
        ELSE
          TPWrite "no file";
        ENDIF
        Open "HOME:/log.txt", log \Read;
        TPWrite "line: """ + ReadStr(log \RemoveCR) + """";
      ENDIF
    ENDFOR
    TPWrite "done";
  ENDPROC
ENDMODULE
