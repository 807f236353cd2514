MODULE routine_data_placeholder
! @format 3
! @section 7.1
! @expect ok
! @description R-7.1-w: a placeholder in the initial value of routine data raises ERR_EXECPHR while the routine is entered, before its body; the routine's own error handler is not asked (it has no statement to retry), the error is raised at the call, and the caller's handler goes on with TRYNEXT after the call.
! @output caller handler TRUE
! @output after the call
! @exit 0
  PROC sub()
    VAR num m := <EXP>;
    TPWrite "wrong: sub body";
  ERROR
    TPWrite "wrong: sub handler";
    RETRY;
  ENDPROC
  PROC main()
    sub;
    TPWrite "after the call";
  ERROR
    TPWrite "caller handler " \Bool:=ERRNO = ERR_EXECPHR;
    TRYNEXT;
  ENDPROC
ENDMODULE
