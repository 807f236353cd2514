MODULE Late
  VAR string tool := "gripper";
  PROC open_gripper(num width)
    TPWrite "gripper open " \Num:=width;
  ENDPROC
  PROC main()
    % "open_" + tool % 25;
    % "open_welder" % 3;
  ERROR
    TPWrite "no such routine: " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE
