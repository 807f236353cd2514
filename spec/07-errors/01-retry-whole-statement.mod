MODULE retry_whole_statement
! @format 3
! @section 4.13
! @section 7.1
! @expect ok
! @description RETRY starts the failing statement again from its beginning: the function call in its left operand, already evaluated once, is evaluated again.
! @output left
! @output handler
! @output left
! @output x=3
! @exit 0
  VAR num divisor := 0;
  FUNC num left()
    TPWrite "left";
    RETURN 6;
  ENDFUNC
  PROC main()
    VAR num x;
    x := left() / divisor;
    TPWrite "x=" \Num:=x;
  ERROR
    TPWrite "handler";
    divisor := 2;
    RETRY;
  ENDPROC
ENDMODULE
