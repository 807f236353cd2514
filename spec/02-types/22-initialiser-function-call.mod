MODULE initialiser_function_call
! @format 2
! @section 2.22
! @section 3.2
! @expect semantic-error 7:20
! @description A constant expression may not contain a function call; refused at the call.
  VAR num b := 2 + twice(2);
  FUNC num twice(num x)
    RETURN 2 * x;
  ENDFUNC
ENDMODULE
