MODULE arrays_different_size
! @format 2
! @section 2.17
! @expect semantic-error 9:10
! @description Arrays with different dimensions are not equal; refused at the right-hand side.
  VAR num a{3};
  VAR num c{4};
  PROC main()
    a := c;
  ENDPROC
ENDMODULE
