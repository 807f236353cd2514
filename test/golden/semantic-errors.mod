MODULE cell
  VAR num a;
  PROC main()
    a := "John";
    MoveL pUnknown, v100, fine, tool0;
    IF a THEN
      RETRY;
    ENDIF
  ENDPROC
ENDMODULE
