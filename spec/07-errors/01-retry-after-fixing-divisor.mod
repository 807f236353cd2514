MODULE retry_after_fixing_divisor
! @format 3
! @section 4.13
! @section 7.1
! @expect ok
! @description RETRY executes the statement that caused the error again (section 4.13): the handler fixes the divisor, and the division then succeeds.
! @output handler
! @output x=5
! @exit 0
  VAR num reg3 := 0;
  PROC main()
    VAR num x;
    x := 5 / reg3;
    TPWrite "x=" \Num:=x;
  ERROR
    IF ERRNO = ERR_DIVZERO THEN
      TPWrite "handler";
      reg3 := 1;
      RETRY;
    ENDIF
  ENDPROC
ENDMODULE
