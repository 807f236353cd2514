MODULE initialiser_constant
! @format 2
! @section 2.23
! @section 3.3
! @expect semantic-error 8:23
! @description A persistent is initialised by a literal expression: a constant name is not a literal; refused at the constant.
  CONST num start := 1;
  PERS num counter := start;
ENDMODULE
