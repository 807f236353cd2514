MODULE Cell
  ! The cell's main routine: picks a part and counts it.
  RECORD partdata
    string name;
    robtarget grip;
  ENDRECORD

  PERS tooldata tGripper := [TRUE, [[0, 0, 100], [1, 0, 0, 0]], [1, [0, 0, 1], [1, 0, 0, 0], 0, 0, 0]];
  CONST robtarget pHome := [[300, 0, 400], [0, 1, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  VAR num nCount := 0;
  VAR partdata part;

  PROC main()
    MoveL pHome, v100, fine, tGripper;
    part.grip := pHome;
    Pick part.grip;
    nCount := nCount + 1;
    TPWrite "Grüße 😀 " \Num := pHome.trans.x;
  ENDPROC
ENDMODULE
