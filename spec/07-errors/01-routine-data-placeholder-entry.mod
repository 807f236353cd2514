MODULE routine_data_placeholder_entry
! @format 3
! @section 7.1
! @expect ok
! @description R-7.1-w: a placeholder in the initial value of the entry routine's data: its error handler, which would RETRY, is not asked; with no call to raise the error at, the system error handler stops the task, at the placeholder.
! @exit 1
! @error ERR_EXECPHR 9:18
  PROC main()
    VAR num m := <EXP>;
    TPWrite "wrong: body";
  ERROR
    TPWrite "wrong: handler";
    RETRY;
  ENDPROC
ENDMODULE
