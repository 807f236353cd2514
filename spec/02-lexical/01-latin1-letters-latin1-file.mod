MODULE latin1_letters_latin1_file
! @section 2.1
! @section 2.3
! @expect ok
! @description Identifiers with Latin-1 letters in a file encoded in ISO 8859-1 (not valid UTF-8): each byte is one character.
  VAR num Ärger := 1;
  VAR num größe := 2;
  VAR num été_à_ÿ;
ENDMODULE
