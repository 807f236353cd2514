MODULE hist
  CONST jointtarget j1 := [[0,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget j2 := [[1,0,0,0,30,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    FOR i FROM 1 TO 100000 DO
      MoveAbsJ j1, v5000, fine, tool0;
      MoveAbsJ j2, v5000, fine, tool0;
    ENDFOR
  ENDPROC
ENDMODULE
