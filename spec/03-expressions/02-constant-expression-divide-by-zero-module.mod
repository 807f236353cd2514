MODULE divide_by_zero_module
! @format 2
! @section 3.2
! @section 3.12
! @section 2.24
! @expect semantic-error 9:22
! @description A module constant divided by a constant whose value is zero: the division is known to fail before the program runs.
  CONST num zero := 10 - 10;
  CONST num ratio := 1 / zero;
  PROC main()
  ENDPROC
ENDMODULE
