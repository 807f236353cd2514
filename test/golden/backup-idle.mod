MODULE Idle
  PROC main()
    TPWrite "idle: this task's files were given by --task";
  ENDPROC
ENDMODULE
