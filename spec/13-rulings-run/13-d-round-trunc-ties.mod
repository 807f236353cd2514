MODULE rulings_round_trunc
! @format 3
! @section 13
! @expect ok
! @description R-13-d: Round rounds the exact value of its argument to Dec decimals, to nearest with ties away from zero (Round(2.5) = 3, Round(-2.5) = -3, Round(0.125\Dec:=2) = 0.13, but Round(1.005\Dec:=2) = 1 since the single nearest 1.005 is below it); Trunc rounds toward zero; RoundDnum and TruncDnum work alike on dnum.
! @output Round(2.5)=3
! @output Round(-2.5)=-3
! @output Round(0.5)=1
! @output Round(1.5)=2
! @output Round(-0.4)=0
! @output Trunc(2.7)=2
! @output Trunc(-2.7)=-2
! @output Round(0.125\Dec:=2)=0.13
! @output Round(1.005\Dec:=2)=1
! @output Round(0.3852138\Dec:=3)=0.385
! @output Round(0.3852138\Dec:=1)=0.4
! @output Trunc(0.3852138\Dec:=3)=0.385
! @output Trunc(-0.3852138\Dec:=3)=-0.385
! @output Round(0.3852138\Dec:=3) = 0.385 TRUE
! @output RoundDnum(1/3\Dec:=3)=0.333
! @output TruncDnum(2/3\Dec:=4)=0.6666
! @output RoundDnum(-2.5)=-3
! @exit 0
  PROC main()
    VAR dnum one := 1;
    VAR dnum two := 2;
    VAR dnum three := 3;
    VAR dnum dhalf := -2.5;
    TPWrite "Round(2.5)=" \Num:=Round(2.5);
    TPWrite "Round(-2.5)=" \Num:=Round(-2.5);
    TPWrite "Round(0.5)=" \Num:=Round(0.5);
    TPWrite "Round(1.5)=" \Num:=Round(1.5);
    TPWrite "Round(-0.4)=" \Num:=Round(-0.4);
    TPWrite "Trunc(2.7)=" \Num:=Trunc(2.7);
    TPWrite "Trunc(-2.7)=" \Num:=Trunc(-2.7);
    TPWrite "Round(0.125\\Dec:=2)=" \Num:=Round(0.125 \Dec:=2);
    TPWrite "Round(1.005\\Dec:=2)=" \Num:=Round(1.005 \Dec:=2);
    TPWrite "Round(0.3852138\\Dec:=3)=" \Num:=Round(0.3852138 \Dec:=3);
    TPWrite "Round(0.3852138\\Dec:=1)=" \Num:=Round(0.3852138 \Dec:=1);
    TPWrite "Trunc(0.3852138\\Dec:=3)=" \Num:=Trunc(0.3852138 \Dec:=3);
    TPWrite "Trunc(-0.3852138\\Dec:=3)=" \Num:=Trunc(-0.3852138 \Dec:=3);
    TPWrite "Round(0.3852138\\Dec:=3) = 0.385 " \Bool:=Round(0.3852138 \Dec:=3) = 0.385;
    TPWrite "RoundDnum(1/3\\Dec:=3)=" \Dnum:=RoundDnum(one / three \Dec:=3);
    TPWrite "TruncDnum(2/3\\Dec:=4)=" \Dnum:=TruncDnum(two / three \Dec:=4);
    TPWrite "RoundDnum(-2.5)=" \Dnum:=RoundDnum(dhalf);
  ENDPROC
ENDMODULE
