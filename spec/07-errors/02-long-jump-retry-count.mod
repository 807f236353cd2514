MODULE long_jump_retry_count
! @format 3
! @section 7.2
! @section 4.13
! @expect ok
! @description After a long jump the retry count of the recovery point is not set to zero (section 7.2): every RETRY after a long jump counts, so with the default limit of 4 the fifth RETRY raises ERR_EXCRTYMAX and the task stops there.
! @output call 1
! @output call 2
! @output call 3
! @output call 4
! @output call 5
! @exit 1
! @error ERR_EXCRTYMAX 18:5
  VAR num calls;
  PROC main()
    routine1;
  ERROR (56)
    RETRY;
  ENDPROC
  PROC routine1()
    routine2;
  ENDPROC
  PROC routine2()
    calls := calls + 1;
    TPWrite "call " \Num:=calls;
    RAISE 56;
  ENDPROC
ENDMODULE
