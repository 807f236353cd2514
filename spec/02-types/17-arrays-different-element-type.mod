MODULE arrays_different_element_type
! @format 2
! @section 2.17
! @expect semantic-error 9:10
! @description Arrays of the same shape with different element types are not equal; refused at the right-hand side.
  VAR num a{3};
  VAR dnum d{3};
  PROC main()
    a := d;
  ENDPROC
ENDMODULE
