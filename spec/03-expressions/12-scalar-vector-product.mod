MODULE scalar_vector_product
! @format 2
! @section 3.12
! @expect ok
! @description Rows * num * pos and pos * num -> pos.
  VAR num k;
  VAR pos p;
  VAR pos r;
  PROC main()
    r := k * p;
    r := p * k;
  ENDPROC
ENDMODULE
