MODULE double_max_accepted
! @section 2.5
! @expect ok
! @description The largest finite IEEE 754 double is within range.
  VAR dnum x;
  PROC main()
    x := 1.7976931348623157E308;
    x := 1E308;
  ENDPROC
ENDMODULE
