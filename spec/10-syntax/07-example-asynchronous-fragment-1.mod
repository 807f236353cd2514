MODULE example_asynchronous_fragment_1
! @section 7.4
! @expect ok
! @description The first program example of section 7.4, each elided part (...) completed with one statement.
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
    TPWrite "log";
  ERROR
    TRYNEXT;
  ENDPROC
ENDMODULE
