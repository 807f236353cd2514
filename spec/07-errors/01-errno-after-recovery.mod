MODULE errno_after_recovery
! @format 3
! @section 7.1
! @section 12
! @expect ok
! @description ERRNO holds the number of the most recent error (chapter 12): it keeps it after the handler has resumed execution with TRYNEXT.
! @output handler 6
! @output later 6
! @exit 0
  PROC main()
    RAISE 6;
    TPWrite "later " \Num:=ERRNO;
  ERROR
    TPWrite "handler " \Num:=ERRNO;
    TRYNEXT;
  ENDPROC
ENDMODULE
