MODULE cell
  VAR num counter;
  CONST robtarget pHome := [[0,0,0],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    counter := countr + 1;
    countr := countr + 2;
    MoveL pHome, v100, z10, tol0, WObj:=wobj0;
    TPWrte "counter";
    TPWrite "counter = ", counter;
  ENDPROC
  PROC reset()
    countr := 0;
  ENDPROC
ENDMODULE
