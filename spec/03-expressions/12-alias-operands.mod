MODULE alias_operands
! @format 2
! @section 3.12
! @expect ok
! @description Note (d) of section 3.12: operands of an alias type give results of the base type (num, dnum, pos).
  ALIAS num level;
  ALIAS pos point;
  ALIAS dnum counter;
  VAR level l;
  VAR point pt;
  VAR counter c;
  VAR num n;
  VAR pos p;
  VAR dnum d;
  PROC main()
    n := -l;
    n := l * l + n;
    p := +pt;
    p := pt + p;
    p := -pt * l;
    d := -c;
    d := c * d;
  ENDPROC
ENDMODULE
