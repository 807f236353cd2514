MODULE comparisons_num
! @format 2
! @section 3.12
! @expect ok
! @description Rows < <= >= > num, num -> bool.
  VAR num a;
  VAR num b;
  VAR bool r;
  PROC main()
    r := a < b;
    r := a <= b;
    r := a >= b;
    r := a > b;
  ENDPROC
ENDMODULE
