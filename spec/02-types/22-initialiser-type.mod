MODULE initialiser_type
! @format 2
! @section 2.22
! @expect semantic-error 6:29
! @description The initialiser's type must equal the variable's; refused at the initialiser.
  VAR string author_name := 25;
ENDMODULE
