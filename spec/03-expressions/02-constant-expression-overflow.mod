MODULE constant_overflow
! @format 2
! @section 3.2
! @section 3.12
! @section 2.13
! @expect semantic-error 9:22
! @description A num constant whose value is beyond single precision (§2.13): the product overflows when the constant expression is evaluated, before the program runs.
  CONST num large := 3E38;
  CONST num twice := large * 2;
  PROC main()
  ENDPROC
ENDMODULE
