MODULE alias_definition_initial_value
! @section 2.15
! @expect syntax-error 5:19
! @description An alias definition has no initial value.
  ALIAS num level := 1;
ENDMODULE
