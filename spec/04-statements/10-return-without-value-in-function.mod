MODULE return_without_value_in_function
! @format 2
! @section 4.10
! @expect semantic-error 7:14
! @description A function returns a value: RETURN without an expression is refused at RETURN.
  FUNC num half(num x)
    IF x = 0 RETURN;
    RETURN x / 2;
  ENDFUNC
ENDMODULE
