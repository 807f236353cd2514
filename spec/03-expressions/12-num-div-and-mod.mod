MODULE num_div_and_mod
! @format 2
! @section 3.12
! @expect ok
! @description Rows DIV and MOD num, num -> num; constant operands represent integers.
  VAR num a;
  VAR num b;
  VAR num r;
  PROC main()
    r := a DIV b;
    r := a MOD b;
    r := 7 DIV 2;
    r := 7 MOD 2 + a DIV 3;
  ENDPROC
ENDMODULE
