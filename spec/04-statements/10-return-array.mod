MODULE return_array
! @format 2
! @section 4.10
! @section 5.5
! @expect semantic-error 9:12
! @description A function cannot return an array value; returning an array variable is refused at the expression.
  FUNC num first()
    VAR num values{3};
    RETURN values;
  ENDFUNC
ENDMODULE
