MODULE module1
  VAR num reg1;
  VAR string string1;
  CONST string string2 := "0-80 characters";
  VAR string string3 := "0-80 characters";
  CONST robtarget p1 := [[0,0,0],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC proc1()
  ENDPROC
  PROC proc2()
    proc1;
    reg1:=1;
    IF reg1=1 proc1;
    IF reg1=1 THEN proc1; ELSE proc2; ENDIF
    WaitTime 1;
    !0-7 ch
    !0-7 chars
    string1:= "0-80 characters";
    TPWrite "0-80 characters";
    MoveL p1,v1000,z50,tool1;
    MoveL [[0,0,0],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],v1000,z50,tool1;
    MoveC [[0,0,0],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],[[0,0,0],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]],v1000,z50,tool1;
    Set do1;
    SetDO do1,1;
    WaitDI di1,1;
    WaitUntil di1=1 AND di2=1;
  ENDPROC
ENDMODULE
