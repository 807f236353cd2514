MODULE variable_definition_empty_dimens
! @section 2.22
! @expect syntax-error 5:13
! @description <variable definition>: '{' <dim> { ',' <dim> } '}' holds at least one dimension.
  VAR num a{};
ENDMODULE
