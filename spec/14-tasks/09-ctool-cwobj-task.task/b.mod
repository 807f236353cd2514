MODULE tool_b
! @task TOOL_B
  VAR taskid nobody;
  PERS bool moved := FALSE;

  FUNC string xyz(pos p)
    RETURN NumToStr(Round(p.x), 0) + " " + NumToStr(Round(p.y), 0) + " " + NumToStr(Round(p.z), 0);
  ENDFUNC

  PROC refused(num k)
    VAR wobjdata o;
    IF k = 1 THEN
      o := CWObj(\TaskName:="NOWHERE");
    ELSE
      o := CWObj(\TaskRef:=nobody);
    ENDIF
    TPWrite "B: not reached";
  ERROR
    IF ERRNO = ERR_TASKNAME TPWrite "B: ERR_TASKNAME";
    RETURN;
  ENDPROC

  PROC main()
    VAR tooldata t;
    VAR wobjdata o;
    WaitUntil moved;
    t := CTool();
    TPWrite "B: tool " + xyz(t.tframe.trans);
    t := CTool(\TaskName:="T_ROB1");
    TPWrite "B: T_ROB1's tool " + xyz(t.tframe.trans);
    t := CTool(\TaskName:="tool_b");
    TPWrite "B: its own name's tool " + xyz(t.tframe.trans);
    o := CWObj(\TaskName:="T_ROB1");
    TPWrite "B: T_ROB1's wobj " + xyz(o.uframe.trans);
    o := CWObj();
    TPWrite "B: its own wobj " + xyz(o.uframe.trans);
    refused 1;
    refused 2;
  ENDPROC
ENDMODULE
