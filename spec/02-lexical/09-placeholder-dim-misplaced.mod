MODULE placeholder_dim_misplaced
! @section 2.9
! @expect syntax-error 5:13
! @description <DIM> stands only in a parameter declaration; a data declaration takes constant expressions.
  VAR num a{<DIM>};
ENDMODULE
