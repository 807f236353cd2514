MODULE initialiser_concatenation
! @format 2
! @section 2.23
! @section 3.3
! @expect semantic-error 7:23
! @description A string concatenation is not a literal expression; refused at its start.
  PERS string name := "cell" + " 1";
ENDMODULE
