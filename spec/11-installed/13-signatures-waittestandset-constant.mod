MODULE sig_waittestandset_constant
! @format 2
! @section 5.2
! @section 13
! @expect semantic-error 9:20
! @description WaitTestAndSet changes its Object (ABB: a variable or persistent used as a semaphore): a constant is refused.
  CONST bool lock := FALSE;
  PROC main()
    WaitTestAndSet lock;
  ENDPROC
ENDMODULE
