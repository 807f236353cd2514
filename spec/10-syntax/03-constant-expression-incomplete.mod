MODULE constant_expression_incomplete
! @section 3.2
! @expect syntax-error 5:21
! @description A constant expression is an <expression>: 1 + needs a right operand.
  CONST num a := 1 +;
ENDMODULE
