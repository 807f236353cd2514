MODULE set_sys_data
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @description SetSysData makes a persistent tooldata or wobjdata the active one, as CTool and CWObj then return, before any move; a loaddata is accepted and changes nothing, as GripLoad (doc/rulings.md R-13-y). A later move's tool and work object replace them.
! @output before 0 0
! @output after 65 -20
! @output load 65 -20
! @output moved 0 0
  PERS tooldata tFlat := [TRUE,[[0,0,65],[1,0,0,0]],[0.5,[0,0,20],[1,0,0,0],0,0,0]];
  PERS wobjdata wShelf := [FALSE,TRUE,"",[[0,-20,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
  PERS loaddata lBox := [3,[0,0,30],[1,0,0,0],0,0,0];
  CONST robtarget q1 := [[300,0,300],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    Show "before";
    SetSysData tFlat;
    SetSysData wShelf;
    Show "after";
    SetSysData lBox;
    Show "load";
    MoveJ q1, v1000, fine, tool0;
    Show "moved";
  ENDPROC
  PROC Show(string what)
    VAR tooldata t;
    VAR wobjdata w;
    t := CTool();
    w := CWObj();
    TPWrite what + " " + NumToStr(t.tframe.trans.z, 0) + " " + NumToStr(w.uframe.trans.y, 0);
  ENDPROC
ENDMODULE
