MODULE num_addition_and_subtraction
! @format 2
! @section 3.12
! @expect ok
! @description Rows + and - num, num -> num.
  VAR num a;
  VAR num b;
  VAR num r;
  PROC main()
    r := a + b;
    r := a - b;
  ENDPROC
ENDMODULE
