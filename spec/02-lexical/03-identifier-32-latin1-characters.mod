MODULE identifier_32_latin1_characters
! @section 2.3
! @section 2.1
! @expect ok
! @description The limit counts characters: 32 Latin-1 letters (64 bytes in UTF-8) are accepted.
  VAR num éééééééééééééééééééééééééééééééé;
ENDMODULE
