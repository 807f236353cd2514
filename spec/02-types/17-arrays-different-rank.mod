MODULE arrays_different_rank
! @format 2
! @section 2.17
! @expect semantic-error 9:10
! @description Arrays with different numbers of dimensions are not equal ({3} and {3,1}); refused at the right-hand side.
  VAR num a{3};
  VAR num m{3, 1};
  PROC main()
    a := m;
  ENDPROC
ENDMODULE
