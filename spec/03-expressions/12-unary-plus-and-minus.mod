MODULE unary_plus_and_minus
! @format 2
! @section 3.12
! @expect ok
! @description Rows unary + and -: +num, +dnum, +pos, -num, -dnum, -pos keep their type.
  VAR num n;
  VAR dnum d;
  VAR pos p;
  PROC main()
    n := +n;
    d := +d;
    p := +p;
    n := -n;
    d := -d;
    p := -p;
  ENDPROC
ENDMODULE
