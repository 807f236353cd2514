MODULE declaration_function_non_value
! @format 2
! @section 2.16
! @section 5.5
! @expect semantic-error 7:8
! @description Table of section 2.16, row function return value, column non-value: illegal; refused at the data type name (a function without RETURN is an execution error only).
  FUNC iodev current_log()
  ENDFUNC
ENDMODULE
