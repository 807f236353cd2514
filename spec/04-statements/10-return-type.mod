MODULE return_type
! @format 2
! @section 4.10
! @expect semantic-error 7:12
! @description The return expression's type must equal the function's; refused at the expression.
  FUNC num half(num x)
    RETURN "half";
  ENDFUNC
ENDMODULE
