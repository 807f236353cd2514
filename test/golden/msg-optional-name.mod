MODULE msg_optional_name
  PROC main()
    PathAccLim TRUE \AccMax:=4, TRUE \DecMax:=4;
  ENDPROC
ENDMODULE
