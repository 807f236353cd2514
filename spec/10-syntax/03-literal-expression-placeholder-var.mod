MODULE literal_expression_placeholder_v
! @section 3.3
! @expect syntax-error 5:17
! @description A literal expression is an <expression>: <VAR> is not one.
  PERS num d := <VAR>;
ENDMODULE
