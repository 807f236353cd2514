MODULE example4
! @section 7.2
! @expect ok
! @description The module example4 of section 7.2: an UNDO handler.
  PROC main()
    routine1;
    ! Error recovery point
  ERROR (56)
    RETRY;
  ENDPROC

  PROC routine1()
    VAR iodev log;
    Open "HOME: " \File:= "FILE1.DOC", log;
    routine2;
    Write log, "routine1 ends with normal execution";
    Close log;
  ERROR
    ! Another error handler
  UNDO
    Close log;
  ENDPROC

  PROC routine2()
    RAISE 56;
  ERROR
    ! This will propagate the error 56 to main
    RAISE;
  ENDPROC
ENDMODULE
