MODULE argnotper_handled
! @format 3
! @section 5.2
! @section 7.1
! @expect ok
! @description ERR_ARGNOTPER is an ordinary execution error: the handler of the routine making the call sees it, and TRYNEXT skips the call.
! @output argnotper=TRUE
! @output skipped
! @exit 0
  VAR num v := 1;
  PROC need_pers(PERS num y)
    TPWrite "wrong";
  ENDPROC
  PROC mid(INOUT num x)
    need_pers x;
    TPWrite "skipped";
  ERROR
    TPWrite "argnotper=" \Bool:=ERRNO = ERR_ARGNOTPER;
    TRYNEXT;
  ENDPROC
  PROC main()
    mid v;
  ENDPROC
ENDMODULE
