MODULE dim_star
! @section 2.22
! @section 5.2
! @expect syntax-error 6:13
! @description '*' marks a conformant dimension of a parameter only; a declared dimension is a constant expression.
  VAR num a{*};
ENDMODULE
