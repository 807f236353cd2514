MODULE identifier_33_latin1_characters
! @section 2.3
! @section 2.1
! @expect lexical-error 6:11
! @description The limit counts characters: 33 Latin-1 letters are refused.
  VAR num ééééééééééééééééééééééééééééééééé;
ENDMODULE
