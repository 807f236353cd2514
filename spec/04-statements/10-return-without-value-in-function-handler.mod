MODULE return_without_value_in_function
! @format 2
! @section 4.10
! @section 7.1
! @expect semantic-error 10:5
! @description In a function's error handler RETURN must specify the return value (section 7.1); refused at RETURN.
  FUNC num safediv(num x, num y)
    RETURN x / y;
  ERROR
    RETURN;
  ENDFUNC
ENDMODULE
