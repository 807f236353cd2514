MODULE byte_text
! @format 3
! @section 13
! @expect ok
! @description ByteToStr writes a byte in decimal, or with \Hex two hexadecimal digits, \Okt three octal digits, \Bin eight binary digits, \Char the character of that code; StrToByte reads each form back, also with fewer digits and lower-case hexadecimal (doc/rulings.md R-13-ab). A byte above 255 and text that is not a byte in that base are ERR_ARGVALERR; a byte that is not an integer is ERR_NOTINTVAL.
! @output 122 7A 172 01111010 z
! @output 122 122 122 122 122
! @output 10 10 5 1
! @output over ERR_ARGVALERR
! @output bad digit ERR_ARGVALERR
! @output too long ERR_ARGVALERR
! @output two chars ERR_ARGVALERR
! @output half ERR_NOTINTVAL
  VAR num b;
  VAR string s;
  PROC main()
    TPWrite ByteToStr(122) + " " + ByteToStr(122 \Hex) + " " + ByteToStr(122 \Okt) + " "
      + ByteToStr(122 \Bin) + " " + ByteToStr(122 \Char);
    TPWrite ValToStr(StrToByte("122")) + " " + ValToStr(StrToByte("7A" \Hex)) + " "
      + ValToStr(StrToByte("172" \Okt)) + " " + ValToStr(StrToByte("01111010" \Bin)) + " "
      + ValToStr(StrToByte("z" \Char));
    TPWrite ValToStr(StrToByte("0a" \Hex)) + " " + ValToStr(StrToByte("010")) + " "
      + ValToStr(StrToByte("101" \Bin)) + " " + ValToStr(StrToByte("1" \Okt));
    Try "over", 1;
    Try "bad digit", 2;
    Try "too long", 3;
    Try "two chars", 4;
    Try "half", 5;
  ENDPROC
  PROC Try(string what, num which)
    TEST which
    CASE 1:
      s := ByteToStr(256);
    CASE 2:
      b := StrToByte("8" \Okt);
    CASE 3:
      b := StrToByte("1FF" \Hex);
    CASE 4:
      b := StrToByte("ab" \Char);
    CASE 5:
      s := ByteToStr(2.5 \Hex);
    ENDTEST
    TPWrite what + " no error";
  ERROR
    IF ERRNO = ERR_ARGVALERR TPWrite what + " ERR_ARGVALERR";
    IF ERRNO = ERR_NOTINTVAL TPWrite what + " ERR_NOTINTVAL";
    RETURN;
  ENDPROC
ENDMODULE
