MODULE rulings_bitset_bitclear
! @format 3
! @section 13
! @expect ok
! @description R-13-h: BitSet and BitClear set and clear one bit of a byte (positions 1..8), BitSetDnum and BitClearDnum of a dnum (positions 1..52).
! @output BitSet 8=128
! @output BitClear 1=254
! @output BitSetDnum 33=4294967296
! @output BitClearDnum 52=2251799813685247
! @exit 0
  PROC main()
    VAR byte b := 0;
    VAR byte c := 255;
    VAR dnum d := 0;
    VAR dnum e := 4503599627370495;
    BitSet b, 8;
    TPWrite "BitSet 8=" \Num:=b;
    BitClear c, 1;
    TPWrite "BitClear 1=" \Num:=c;
    BitSetDnum d, 33;
    TPWrite "BitSetDnum 33=" \Dnum:=d;
    BitClearDnum e, 52;
    TPWrite "BitClearDnum 52=" \Dnum:=e;
  ENDPROC
ENDMODULE
