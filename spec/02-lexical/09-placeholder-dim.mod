MODULE placeholder_dim
! @section 2.9
! @section 5.2
! @expect ok
! @description <DIM> stands for the array dimensions of a parameter.
  PROC p(num a{<DIM>}, VAR num b{<DIM>})
  ENDPROC
ENDMODULE
