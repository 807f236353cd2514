MODULE rulings_bit_functions
! @format 3
! @section 13
! @expect ok
! @description R-13-h: the bit functions work on bytes 0..255 with bit positions 1..8; bits shifted past the width are lost and BitNeg complements within 8 bits.
! @output BitAnd(12,10)=8
! @output BitOr(12,10)=14
! @output BitXOr(12,10)=6
! @output BitNeg(0)=255
! @output BitNeg(170)=85
! @output BitLSh(1,3)=8
! @output BitLSh(128,1)=0
! @output BitLSh(3,7)=128
! @output BitRSh(8,3)=1
! @output BitRSh(1,1)=0
! @output BitCheck(5,1)=TRUE
! @output BitCheck(5,2)=FALSE
! @output BitCheck(128,8)=TRUE
! @exit 0
  PROC main()
    VAR byte b := 12;
    TPWrite "BitAnd(12,10)=" \Num:=BitAnd(b, 10);
    TPWrite "BitOr(12,10)=" \Num:=BitOr(12, 10);
    TPWrite "BitXOr(12,10)=" \Num:=BitXOr(12, 10);
    TPWrite "BitNeg(0)=" \Num:=BitNeg(0);
    TPWrite "BitNeg(170)=" \Num:=BitNeg(170);
    TPWrite "BitLSh(1,3)=" \Num:=BitLSh(1, 3);
    TPWrite "BitLSh(128,1)=" \Num:=BitLSh(128, 1);
    TPWrite "BitLSh(3,7)=" \Num:=BitLSh(3, 7);
    TPWrite "BitRSh(8,3)=" \Num:=BitRSh(8, 3);
    TPWrite "BitRSh(1,1)=" \Num:=BitRSh(1, 1);
    TPWrite "BitCheck(5,1)=" \Bool:=BitCheck(5, 1);
    TPWrite "BitCheck(5,2)=" \Bool:=BitCheck(5, 2);
    TPWrite "BitCheck(128,8)=" \Bool:=BitCheck(128, 8);
  ENDPROC
ENDMODULE
