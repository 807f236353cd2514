MODULE example_motion_error
! @section 7.6
! @expect ok
! @description The first example of section 7.6.
  PROC main()
    MoveJ p10, v200, fine, tool0;
    MoveJ p20, v200, fine, tool0;
  ERROR
    TEST ERRNO
    CASE ERR_COLL_STOP:
      StorePath;
      MoveJ p30, v200, fine, tool0;
      RestoPath;
      StartMove;
    ENDTEST
    RETRY;
  ENDPROC
ENDMODULE
