MODULE retry_in_error_handler
! @format 2
! @section 4.13
! @section 7.1
! @expect ok
! @description RETRY in error handlers of procedures, functions and traps, also nested in IF.
  VAR num reg3;
  PROC main()
    reg3 := 1 / reg3;
  ERROR
    IF ERRNO = ERR_DIVZERO THEN
      reg3 := 1;
      RETRY;
    ENDIF
    RAISE;
  ENDPROC
  FUNC num f()
    RETURN 1 / reg3;
  ERROR
    reg3 := 1;
    RETRY;
  ENDFUNC
  TRAP on_event
    reg3 := 1 / reg3;
  ERROR
    RETRY;
  ENDTRAP
ENDMODULE
