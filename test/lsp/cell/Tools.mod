MODULE Tools
  ! Zähler: the picks so far (this file is Latin-1, as older controllers save it)
  PROC Pick(robtarget pAt)
    VAR num k;
    MoveL Offs(pAt, 0, 0, 50), v100, z10, tGripper \WObj:=wobj0;
    TPWrite "Zähler: " \Num:=nCount;
    k := nCount * 2;
  ENDPROC
ENDMODULE
