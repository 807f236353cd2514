MODULE persistent_definition_empty_dime
! @section 2.23
! @expect syntax-error 5:14
! @description <persistent definition>: '{' <dim> { ',' <dim> } '}' holds at least one dimension.
  PERS num x{} := [1];
ENDMODULE
