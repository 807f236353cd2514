MODULE four_dimensions
! @format 2
! @section 2.22
! @expect semantic-error 6:30
! @description An array has 1, 2 or 3 dimensions; a fourth dimension is refused at its expression.
  VAR num tesseract{2, 2, 2, 2};
ENDMODULE
