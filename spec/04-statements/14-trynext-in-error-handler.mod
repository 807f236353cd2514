MODULE trynext_in_error_handler
! @format 2
! @section 4.14
! @section 7.1
! @expect ok
! @description TRYNEXT in error handlers (section 4.14's example pattern) and at an error recovery point (section 7.2).
  PROC main()
    DebugBreak;
  ERROR
    IF ERRNO = ERR_DIVZERO THEN
      TRYNEXT;
    ENDIF
    RAISE;
  ENDPROC
  PROC recover()
    main;
  ERROR (56, ERR_DIVZERO)
    TRYNEXT;
  ENDPROC
ENDMODULE
