MODULE rulings_num_text
! @format 3
! @section 13
! @expect ok
! @description R-13-a: TPWrite \Num and ValToStr write a num within 0.000005 of an integer n with |n| <= 8388608 as that integer; any other with 6 significant digits, positional for decimal exponents -4..5 and d.dddddE+XX otherwise, trailing zeros removed, no minus sign on a value written as 0; pos, orient, pose and arrays are written [a,b,c] without spaces, their numbers the same way.
! @output 5=5
! @output 1/3=0.333333
! @output 1E-7=0
! @output -1E-7=0
! @output 2.000001=2
! @output 1.99999=1.99999
! @output 123456789=1.23457E+08
! @output 16777216=1.67772E+07
! @output 8388608=8388608
! @output -8388608=-8388608
! @output 1234567.5=1.23457E+06
! @output 123456.7=123457
! @output 0.0001234=0.0001234
! @output 1.234E-5=1.234E-05
! @output 0.00001=1E-05
! @output -2.5=-2.5
! @output pos=[0.5,0.333333,0]
! @output orient=[1,0,0,0]
! @output 5
! @output -5
! @output 1.23457
! @output 0.333333
! @output 1.67772E+07
! @output -0.5
! @output 0
! @output [1.5,-2,0]
! @output [1,0,0,0]
! @output [[1,2,3],[1,0,0,0]]
! @output [1,0.25,3]
! @output TRUE
! @exit 0
  PROC main()
    VAR num one := 1;
    VAR num three := 3;
    VAR pos p := [0.5, 0, 1E-7];
    VAR orient o := [1, 0, 0, 0.000001];
    VAR pos q := [1.5, -2, 1E-7];
    VAR orient unit := [1, 0, 0, 0];
    VAR pose ps := [[1, 2, 3], [1, 0, 0, 0]];
    VAR num a{3} := [1, 0.25, 3];
    p.y := one / three;
    TPWrite "5=" \Num:=5;
    TPWrite "1/3=" \Num:=one / three;
    TPWrite "1E-7=" \Num:=1E-7;
    TPWrite "-1E-7=" \Num:=-1E-7;
    TPWrite "2.000001=" \Num:=2.000001;
    TPWrite "1.99999=" \Num:=1.99999;
    TPWrite "123456789=" \Num:=123456789;
    TPWrite "16777216=" \Num:=16777216;
    TPWrite "8388608=" \Num:=8388608;
    TPWrite "-8388608=" \Num:=-8388608;
    TPWrite "1234567.5=" \Num:=1234567.5;
    TPWrite "123456.7=" \Num:=123456.7;
    TPWrite "0.0001234=" \Num:=0.0001234;
    TPWrite "1.234E-5=" \Num:=1.234E-5;
    TPWrite "0.00001=" \Num:=0.00001;
    TPWrite "-2.5=" \Num:=-2.5;
    TPWrite "pos=" \Pos:=p;
    TPWrite "orient=" \Orient:=o;
    TPWrite ValToStr(5);
    TPWrite ValToStr(-5);
    TPWrite ValToStr(1.23456789);
    TPWrite ValToStr(one / three);
    TPWrite ValToStr(16777216);
    TPWrite ValToStr(-0.5);
    TPWrite ValToStr(-0.0000001);
    TPWrite ValToStr(q);
    TPWrite ValToStr(unit);
    TPWrite ValToStr(ps);
    TPWrite ValToStr(a);
    TPWrite ValToStr(TRUE);
  ENDPROC
ENDMODULE
