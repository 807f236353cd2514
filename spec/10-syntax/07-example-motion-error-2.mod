MODULE MainModule
! @section 7.6
! @expect ok
! @description Example 2 of section 7.6: an optional argument as the first argument, then a comma.
  PROC main()
    MoveJ p10, v1000, z50, tool0;
    Routine1;
  ENDPROC
  PROC Routine1()
    Routine2;
    WaitTime 10; !Program pointer
  ERROR
    TPWrite "Routine1";
  ENDPROC
  PROC Routine2()
    MoveJ\Conc, p20, v10, z50, tool0; !Motion pointer
    MoveJ\Conc, p30, v10, z50, tool0;
  ERROR
    TPWrite "Routine2";
    StorePath;
    RestoPath;
    StartMoveRetry;
  ENDPROC
ENDMODULE
