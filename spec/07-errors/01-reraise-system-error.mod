MODULE reraise_system_error
! @format 3
! @section 4.11
! @section 7.1
! @expect ok
! @description RAISE; passes a system error on unchanged: the caller's handler sees ERR_DIVZERO.
! @output divzero in main=TRUE
! @exit 0
  PROC p()
    VAR num d;
    VAR num x;
    x := 1 / d;
  ERROR
    RAISE;
  ENDPROC
  PROC main()
    p;
  ERROR
    TPWrite "divzero in main=" \Bool:=ERRNO = ERR_DIVZERO;
    TRYNEXT;
  ENDPROC
ENDMODULE
