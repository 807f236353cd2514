MODULE retry_limit_four_retries
! @format 3
! @section 4.13
! @section 7.5
! @expect ok
! @description Four RETRYs are allowed by default (section 7.5): the statement fails four times and succeeds at the fifth execution.
! @output retry 1
! @output retry 2
! @output retry 3
! @output retry 4
! @output x=2
! @exit 0
  VAR num n;
  VAR num d;
  PROC main()
    VAR num x;
    x := 10 / d;
    TPWrite "x=" \Num:=x;
  ERROR
    n := n + 1;
    TPWrite "retry " \Num:=n;
    IF n = 4 d := 5;
    RETRY;
  ENDPROC
ENDMODULE
