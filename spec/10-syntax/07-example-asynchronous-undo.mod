MODULE example_asynchronous_undo
! @section 7.4
! @expect ok
! @description The UNDO example of section 7.4; its pseudo-code (Open .. logile ..;) and elisions completed.
  VAR iodev logfile;
  PROC main()
    my_process;
  ERROR
    RETRY;
  ENDPROC
  PROC my_process()
    MoveL p1, v300, z10, tool1;
    write_log;
    MoveL p2, v300, z10, tool1;
  ERROR
    RETRY;
  ENDPROC
  PROC write_log()
    Open "HOME:" \File:= "log.txt", logfile;
    Write logfile, "log";
    Close logfile;
  ERROR
    RETRY;
  UNDO
    Close logfile;
  ENDPROC
ENDMODULE
