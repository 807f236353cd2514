MODULE example
! @section 7.2
! @expect ok
! @description The module example of section 7.2: an error recovery point.
  PROC main()
  ! Do something important
  myRoutine;
  ERROR (56, ERR_DIVZERO)
  RETRY;
  ENDPROC
ENDMODULE
