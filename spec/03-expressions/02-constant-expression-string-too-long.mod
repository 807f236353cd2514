MODULE constant_string_too_long
! @format 2
! @section 3.2
! @section 3.12
! @section 2.13
! @expect semantic-error 10:30
! @description A string constant longer than 80 characters (§2.13) built by concatenating two constants: the concatenation fails before the program runs.
  CONST string forty := "0123456789012345678901234567890123456789";
  CONST string eighty := forty + forty;
  CONST string eighty_one := eighty + "!";
  PROC main()
  ENDPROC
ENDMODULE
