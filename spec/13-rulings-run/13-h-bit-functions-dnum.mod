MODULE rulings_bit_functions_dnum
! @format 3
! @section 13
! @expect ok
! @description R-13-h: the dnum bit functions work on 0..2^52-1 with bit positions 1..52; bits shifted past bit 52 are lost and BitNegDnum complements within 52 bits.
! @output BitCheckDnum(2^51,52)=TRUE
! @output BitCheckDnum(2^51,51)=FALSE
! @output BitNegDnum(0)=4503599627370495
! @output BitLShDnum(2^51,1)=0
! @output BitRShDnum(2^52-1,51)=1
! @output BitAndDnum=4294967296
! @output BitOrDnum=4294967297
! @output BitXOrDnum=4503599627370494
! @exit 0
  PROC main()
    VAR dnum top := 2251799813685248;
    VAR dnum all := 4503599627370495;
    VAR dnum bit33 := 4294967296;
    VAR dnum one := 1;
    VAR dnum zero := 0;
    TPWrite "BitCheckDnum(2^51,52)=" \Bool:=BitCheckDnum(top, 52);
    TPWrite "BitCheckDnum(2^51,51)=" \Bool:=BitCheckDnum(top, 51);
    TPWrite "BitNegDnum(0)=" \Dnum:=BitNegDnum(zero);
    TPWrite "BitLShDnum(2^51,1)=" \Dnum:=BitLShDnum(top, 1);
    TPWrite "BitRShDnum(2^52-1,51)=" \Dnum:=BitRShDnum(all, 51);
    TPWrite "BitAndDnum=" \Dnum:=BitAndDnum(all, bit33);
    TPWrite "BitOrDnum=" \Dnum:=BitOrDnum(bit33, one);
    TPWrite "BitXOrDnum=" \Dnum:=BitXOrDnum(all, one);
  ENDPROC
ENDMODULE
