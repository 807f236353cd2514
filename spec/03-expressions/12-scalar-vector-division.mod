MODULE scalar_vector_division
! @format 2
! @section 3.12
! @expect ok
! @description Row / pos / num -> pos.
  VAR pos p;
  VAR num k;
  VAR pos r;
  PROC main()
    r := p / k;
  ENDPROC
ENDMODULE
