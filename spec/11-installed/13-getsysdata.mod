MODULE get_sys_data
! @format 3
! @section 13
! @expect ok
! @description GetSysData DestObject \ObjectName (ABB, RAPID Instructions): the active tool and work object copied into a persistent, their names into a string: tool0 and wobj0 before any move, then those of the last move (and of SetSysData); a loaddata is load0 (doc/rulings.md R-13-getsysdata1). An argument of another type: ERR_ARGVALERR.
! @output tool0 0 wobj0
! @output tGun 150 wTable 200
! @output tGun2 75
! @output load0 0
! @output ERR_ARGVALERR
  CONST robtarget p1 := [[300,-100,300],[0,0,1,0],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS tooldata tGun := [TRUE,[[0,0,150],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];
  PERS tooldata tGun2 := [TRUE,[[0,0,75],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];
  PERS wobjdata wTable := [FALSE,TRUE,"",[[0,0,200],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
  PERS tooldata tNow := [TRUE,[[0,0,1],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];
  PERS wobjdata wNow := [FALSE,TRUE,"",[[0,0,0],[1,0,0,0]],[[0,0,0],[1,0,0,0]]];
  PERS loaddata lNow := [1,[0,0,1],[1,0,0,0],0,0,0];
  PERS num nNow := 0;
  VAR string toolName;
  VAR string wobjName;
  PROC main()
    GetSysData tNow \ObjectName:=toolName;
    GetSysData wNow \ObjectName:=wobjName;
    TPWrite toolName + " " + NumToStr(tNow.tframe.trans.z, 0) + " " + wobjName;
    MoveL Offs(p1, 0, 0, -200), v1000, fine, tGun \WObj:=wTable;
    GetSysData tNow \ObjectName:=toolName;
    GetSysData wNow \ObjectName:=wobjName;
    TPWrite toolName + " " + NumToStr(tNow.tframe.trans.z, 0) + " " + wobjName + " " + NumToStr(wNow.uframe.trans.z, 0);
    SetSysData tGun2;
    GetSysData tNow \ObjectName:=toolName;
    TPWrite toolName + " " + NumToStr(tNow.tframe.trans.z, 0);
    GetSysData lNow \ObjectName:=toolName;
    TPWrite toolName + " " + NumToStr(lNow.mass, 0);
    GetSysData nNow;
  ERROR
    IF ERRNO = ERR_ARGVALERR THEN
      TPWrite "ERR_ARGVALERR";
      RETURN;
    ENDIF
  ENDPROC
ENDMODULE
