MODULE rulings_maxintval_first
! @format 3
! @section 3.12
! @section 7.1
! @expect ok
! @description R-3.12-b: 16777216 is an integer-valued single outside num's exact sub-domain, so 16777216 DIV 0 stops the task with ERR_MAXINTVAL (operands are checked before the divisor), at the statement evaluating it.
! @output before
! @exit 1
! @error ERR_MAXINTVAL 16:5
  PROC main()
    VAR num big := 16777216;
    VAR num zero := 0;
    VAR num x;
    TPWrite "before";
    x := 1;
    x := big DIV zero;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
