MODULE trynext_statement
! @section 4.14
! @expect ok
! @description The example of section 4.14, completed into a function.
  VAR iodev logfile;
  FUNC bool log_remove()
    ! Remove the logfile
    delete logfile;
    RETURN TRUE;
  ERROR
    IF ERRNO = ERR_FILEACC THEN
      ! Logfile already removed - Ignore
      TRYNEXT;
    ENDIF
    ! propagate "unexpected" error
    RAISE;
  ENDFUNC
ENDMODULE
