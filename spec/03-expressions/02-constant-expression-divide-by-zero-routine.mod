MODULE divide_by_zero_routine
! @format 2
! @section 3.2
! @section 3.12
! @section 2.22
! @expect semantic-error 10:18
! @description A routine variable's initial value is a constant expression (§2.22, §3.2): it holds no variable, persistent or function call, so it is known before the program runs, and a division by zero in it is a static error, at the operation.
  PROC main()
    VAR num ok := 6 / 3;
    VAR num x := 1 / 0;
    x := ok;
  ENDPROC
ENDMODULE
