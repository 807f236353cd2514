MODULE double_smallest_accepted
! @section 2.5
! @expect ok
! @description The smallest subnormal double (about 4.9E-324) is within range.
  VAR dnum x;
  PROC main()
    x := 4.9E-324;
    x := 2.2250738585072014E-308;
  ENDPROC
ENDMODULE
