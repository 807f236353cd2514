MODULE initialiser_function_call
! @format 2
! @section 2.23
! @section 3.3
! @expect semantic-error 7:17
! @description A function call is not a literal expression; refused at the call.
  PERS num p := twice(1);
  FUNC num twice(num x)
    RETURN 2 * x;
  ENDFUNC
ENDMODULE
