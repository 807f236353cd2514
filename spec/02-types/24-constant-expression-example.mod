MODULE constant_expression_example
! @format 2
! @section 2.24
! @section 3.2
! @expect ok
! @description The constant expressions of section 3.2, and a constant in a routine.
  CONST num radius := 25;
  CONST num pi := 3.141592654;
  ! constant expression
  CONST num area := pi * radius * radius;
  CONST errnum escape := 10;
  PROC main()
    CONST num diameter := 2 * radius;
  ENDPROC
ENDMODULE
