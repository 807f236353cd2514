MODULE bitset_dnum
! @format 3
! @section 13
! @expect ok
! @description BitSet and BitClear (ABB's RAPID reference: "BitSet BitData | DnumData, BitPos", bit positions 1-8 in a byte, 1-52 in a dnum) change one bit of a byte or of a dnum variable or persistent, the type of the argument choosing (doc/rulings.md R-13-sys4); BitCheck reads a byte, BitCheckDnum a dnum. A position beyond the width, and a byte variable holding more than 255, are ERR_ARGVALERR (R-13-h).
! @output byte 129
! @output dnum 2251799813685249
! @output checked TRUE TRUE FALSE
! @output cleared 1
! @output cleared 1
! @output persistent 4294967296
! @output byte bit 9 ERR_ARGVALERR
! @output dnum bit 53 ERR_ARGVALERR
! @output not a byte ERR_ARGVALERR
  VAR byte b := 1;
  VAR dnum d := 1;
  PERS dnum pd := 0;
  VAR num big := 300;
  PROC main()
    BitSet b, 8;
    TPWrite "byte " \Num:=b;
    BitSet d, 52;
    TPWrite "dnum " \Dnum:=d;
    TPWrite "checked " + ValToStr(BitCheck(b, 8)) + " " + ValToStr(BitCheckDnum(d, 52)) + " "
      + ValToStr(BitCheckDnum(d, 51));
    BitClear b, 8;
    BitClear d, 52;
    TPWrite "cleared " \Num:=b;
    TPWrite "cleared " + ValToStr(d);
    BitSet pd, 33;
    TPWrite "persistent " \Dnum:=pd;
    Try "byte bit 9", 1;
    Try "dnum bit 53", 2;
    Try "not a byte", 3;
  ENDPROC
  PROC Try(string what, num which)
    TEST which
    CASE 1:
      BitSet b, 9;
    CASE 2:
      BitClear d, 53;
    CASE 3:
      BitSet big, 1;
    ENDTEST
    TPWrite what + " no error";
  ERROR
    IF ERRNO = ERR_ARGVALERR TPWrite what + " ERR_ARGVALERR";
    RETURN;
  ENDPROC
ENDMODULE
