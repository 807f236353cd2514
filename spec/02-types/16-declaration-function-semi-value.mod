MODULE declaration_function_semi_value
! @format 2
! @section 2.16
! @section 5.5
! @expect semantic-error 7:8
! @description Table of section 2.16, row function return value, column semi-value: illegal; refused at the data type name.
  FUNC signaldi current_input()
  ENDFUNC
ENDMODULE
