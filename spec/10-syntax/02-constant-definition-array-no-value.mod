MODULE constant_definition_array_no_val
! @section 2.24
! @expect syntax-error 5:17
! @description <constant definition> requires ':=' <constant expression>, arrays included.
  CONST num x{2};
ENDMODULE
