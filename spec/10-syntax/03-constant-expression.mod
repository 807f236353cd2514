MODULE constant_expression
! @section 3.2
! @expect ok
! @description The example of section 3.2.
  CONST num radius := 25;
  CONST num pi := 3.141592654;
  ! constant expression
  CONST num area := pi * radius * radius;
ENDMODULE
