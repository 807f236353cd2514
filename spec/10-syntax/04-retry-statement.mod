MODULE retry_statement
! @section 4.13
! @expect ok
! @description The example of section 4.13 (garbled in print), completed into a function.
  VAR iodev logfile;
  FUNC bool log_open()
    ! open logfile
    open \append, logfile, "temp.log";
    RETURN TRUE;
  ERROR
    IF ERRNO = ERR_FILEACC THEN
      ! create missing file
      create "temp.log";
      ! resume execution
      RETRY;
    ENDIF
    ! propagate "unexpected" error
    RAISE;
  ENDFUNC
ENDMODULE
