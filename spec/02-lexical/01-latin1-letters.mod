MODULE latin1_letters
! @section 2.1
! @expect ok
! @description Every Latin-1 letter (U+00C0-U+00D6, U+00D8-U+00F6, U+00F8-U+00FF) may appear in an identifier; the file is UTF-8.
  VAR num ÀÁÂÃÄÅÆÇÈÉÊËÌÍÎÏÐÑÒÓÔÕÖ;
  VAR num ØÙÚÛÜÝÞß;
  VAR num àáâãäåæçèéêëìíîïðñòóôõö;
  VAR num øùúûüýþÿ;
  VAR num Straße_2 := 1;
ENDMODULE
