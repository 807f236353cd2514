MODULE retry_call
! @format 3
! @section 4.13
! @section 7.1
! @section 2.21
! @expect ok
! @description When the failing statement is a call (the error came from the called procedure, which has no handler), RETRY calls it again: a new call, with fresh routine data.
! @output attempt 1 mine=1
! @output main handler
! @output attempt 2 mine=1
! @output done
! @exit 0
  VAR num attempts;
  PROC work()
    VAR num mine;
    mine := mine + 1;
    attempts := attempts + 1;
    TPWrite "attempt " + NumToStr(attempts, 0) + " mine=" + NumToStr(mine, 0);
    IF attempts < 2 RAISE 7;
  ENDPROC
  PROC main()
    work;
    TPWrite "done";
  ERROR
    TPWrite "main handler";
    RETRY;
  ENDPROC
ENDMODULE
