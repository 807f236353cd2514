MODULE arrays_same_dimensions
! @format 2
! @section 2.17
! @expect ok
! @description Arrays with the same number of dimensions and the same dimensions and element type are equal (section 3.6's row := column).
  VAR num row{3};
  VAR num column{3};
  VAR pos m1{2, 3};
  VAR pos m2{2, 3};
  PROC main()
    row := column;
    m1 := m2;
  ENDPROC
ENDMODULE
