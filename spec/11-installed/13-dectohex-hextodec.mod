MODULE dec_to_hex
! @format 3
! @section 13
! @expect ok
! @description DecToHex and HexToDec (ABB's RAPID reference: a number in a string from base 10 to base 16 and back, from 0 to 9223372036854775807 or 7FFFFFFFFFFFFFFF; the examples DecToHex("99999999") and HexToDec("5F5E0FF")). Hexadecimal is written with upper-case letters and read in either case; leading zeros are read and not written; an empty text, a sign, a blank, a prefix 0x, a digit of another base or a number beyond the range is ERR_ARGVALERR (doc/rulings.md R-13-sys3).
! @output 5F5E0FF 99999999
! @output 0 0 FF 255
! @output 7FFFFFFFFFFFFFFF 9223372036854775807
! @output 2748 10 ABC
! @output empty ERR_ARGVALERR
! @output sign ERR_ARGVALERR
! @output blank ERR_ARGVALERR
! @output prefix ERR_ARGVALERR
! @output hex digit ERR_ARGVALERR
! @output too big ERR_ARGVALERR
! @output too big hex ERR_ARGVALERR
  VAR string s;
  PROC main()
    TPWrite DecToHex("99999999") + " " + HexToDec("5F5E0FF");
    TPWrite DecToHex("0") + " " + HexToDec("0") + " " + DecToHex("255") + " " + HexToDec("ff");
    TPWrite DecToHex("9223372036854775807") + " " + HexToDec("7FFFFFFFFFFFFFFF");
    TPWrite HexToDec("abc") + " " + HexToDec("000A") + " " + DecToHex("0002748");
    Try "empty", 1;
    Try "sign", 2;
    Try "blank", 3;
    Try "prefix", 4;
    Try "hex digit", 5;
    Try "too big", 6;
    Try "too big hex", 7;
  ENDPROC
  PROC Try(string what, num which)
    TEST which
    CASE 1:
      s := DecToHex("");
    CASE 2:
      s := DecToHex("-1");
    CASE 3:
      s := HexToDec(" FF");
    CASE 4:
      s := HexToDec("0xFF");
    CASE 5:
      s := DecToHex("1F");
    CASE 6:
      s := DecToHex("9223372036854775808");
    CASE 7:
      s := HexToDec("8000000000000000");
    ENDTEST
    TPWrite what + " no error";
  ERROR
    IF ERRNO = ERR_ARGVALERR TPWrite what + " ERR_ARGVALERR";
    RETURN;
  ENDPROC
ENDMODULE
