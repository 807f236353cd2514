MODULE example
! @section 7.6
! @expect ok
! @description Example 3 of section 7.6, with its irregular indentation.
   PROC main()
     proc1;
    ERROR
      IF ERRNO=ERR_COLL_STOP THEN
      StartMoveRetry;
      ENDIF
    ENDPROC
   PROC proc1()
      !Move instruction
      !Move instruction
    ERROR
      IF ERRNO=ERR_COLL_STOP THEN
     RAISE;
     ENDIF
    ENDPROC
ENDMODULE
