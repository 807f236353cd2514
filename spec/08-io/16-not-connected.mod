MODULE not_connected
! @format 3
! @section 2.16
! @section 13
! @expect ok
! @io io/basic.io
! @description A signal variable declared in the program is connected to no signal of the I/O configuration: SetDO on it raises ERR_NO_ALIASIO_DEF (doc/rulings.md R-8-a), which an error handler can take.
! @output handled TRUE
! @output after
  VAR signaldo do_local;
  PROC main()
    SetDO do_local, 1;
    TPWrite "after";
  ERROR
    TPWrite "handled " \Bool:=(ERRNO = ERR_NO_ALIASIO_DEF);
    TRYNEXT;
  ENDPROC
ENDMODULE
