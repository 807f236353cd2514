MODULE div_and_mod
! @format 3
! @section 3.12
! @expect ok
! @description DIV and MOD of integer num values; with a negative operand they truncate toward zero and the remainder takes the sign of the dividend (doc/rulings.md R-3.12).
! @output 7 DIV 2=3
! @output 7 MOD 2=1
! @output -7 DIV 2=-3
! @output -7 MOD 2=-1
! @output 7 DIV -2=-3
! @output 7 MOD -2=1
! @output 6 MOD 3=0
! @exit 0
  PROC main()
    VAR num a := 7;
    VAR num b := 2;
    VAR num na := -7;
    VAR num nb := -2;
    VAR num c := 6;
    VAR num d := 3;
    TPWrite "7 DIV 2=" \Num:=a DIV b;
    TPWrite "7 MOD 2=" \Num:=a MOD b;
    TPWrite "-7 DIV 2=" \Num:=na DIV b;
    TPWrite "-7 MOD 2=" \Num:=na MOD b;
    TPWrite "7 DIV -2=" \Num:=a DIV nb;
    TPWrite "7 MOD -2=" \Num:=a MOD nb;
    TPWrite "6 MOD 3=" \Num:=c MOD d;
  ENDPROC
ENDMODULE
