MODULE constant_declaration_no_value
! @section 2.24
! @expect syntax-error 5:14
! @description <constant definition> requires ':=' <constant expression>.
  CONST num x;
ENDMODULE
