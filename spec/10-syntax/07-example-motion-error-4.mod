MODULE example_motion_error_4
! @section 7.6
! @expect ok
! @description Example 4 of section 7.6 (its misprint WriteCfqData read as WriteCfgData).
PROC main()
  WriteCfgData "/SYS/SYS_MISC/CollisionErrorHandling", "Value", 1;
  MoveJ p10, v200, fine, tool0;
  MoveJ p20, v200, fine, tool0;
  WriteCfgData "/SYS/SYS_MISC/CollisionErrorHandling", "Value", 0;
ERROR
  TEST ERRNO
  CASE ERR_COLL_STOP:
    StorePath;
    MoveJ p30, v200, fine, tool0;
    RestoPath;
    StartMove;
    ENDTEST
   RETRY;
UNDO
  WriteCfgData "/SYS/SYS_MISC/CollisionErrorHandling", "Value", 0;
ENDPROC
ENDMODULE
