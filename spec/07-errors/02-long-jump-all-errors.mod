MODULE long_jump_all_errors
! @format 3
! @section 7.2
! @expect ok
! @description ERROR (LONG_JMP_ALL_ERR) is a recovery point for every kind of error (section 7.2): a division by zero two calls down reaches main, skipping the ordinary handler in between.
! @output recovery point divzero=TRUE
! @exit 0
  PROC main()
    middle;
  ERROR (LONG_JMP_ALL_ERR)
    TPWrite "recovery point divzero=" \Bool:=ERRNO = ERR_DIVZERO;
    RETURN;
  ENDPROC
  PROC middle()
    deep;
  ERROR
    TPWrite "wrong: middle handler";
    RETURN;
  ENDPROC
  PROC deep()
    VAR num d;
    VAR num x;
    x := 1 / d;
  ENDPROC
ENDMODULE
