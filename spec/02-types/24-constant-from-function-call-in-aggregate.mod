MODULE constant_from_function_call_in
! @format 2
! @section 2.24
! @section 3.2
! @expect semantic-error 7:22
! @description A constant expression may not contain a function call at any level; refused at the call inside the aggregate.
  CONST pos p := [1, twice(1), 3];
  FUNC num twice(num x)
    RETURN 2 * x;
  ENDFUNC
ENDMODULE
