MODULE division_by_zero_at_run_time
! @format 2
! @section 3.12
! @section 1.4
! @expect ok
! @description Division by zero is an execution error (section 1.4), not a static one.
  VAR num n;
  PROC main()
    n := n / 0;
    n := n DIV 0;
    n := 5 MOD 0;
  ENDPROC
ENDMODULE
