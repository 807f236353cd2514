MODULE initialiser_type
! @format 2
! @section 2.23
! @expect semantic-error 6:17
! @description The literal expression's type must equal the persistent's; refused at the initialiser.
  PERS num p := "zero";
ENDMODULE
