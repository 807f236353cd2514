MODULE example_asynchronous_fragment_2
! @section 7.4
! @expect ok
! @description The second program example of section 7.4, each elided part completed with one statement.
  PROC main()
    my_process;
    my_process;
  ERROR
    RETRY;
  ENDPROC
  PROC my_process()
    MoveL p1, v300, z10, tool1;
    MoveL p2, v300, z10, tool1;
  ERROR
    RETRY;
  ENDPROC
ENDMODULE
