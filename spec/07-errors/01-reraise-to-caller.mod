MODULE reraise_to_caller
! @format 3
! @section 4.11
! @section 7.1
! @expect ok
! @description RAISE without number in an error handler raises the same (current) error again at the call of the routine (section 4.11): the caller's handler sees the same ERRNO.
! @output p handler 33
! @output main handler 33
! @output after p
! @exit 0
  PROC p()
    RAISE 33;
  ERROR
    TPWrite "p handler " \Num:=ERRNO;
    RAISE;
  ENDPROC
  PROC main()
    p;
    TPWrite "after p";
  ERROR
    TPWrite "main handler " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE
