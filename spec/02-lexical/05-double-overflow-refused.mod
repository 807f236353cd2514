MODULE double_overflow_refused
! @section 2.5
! @expect lexical-error 7:10
! @description A literal just above the largest double (it rounds to infinity) is out of the range of IEEE 754.
  VAR dnum x;
  PROC main()
    x := 1.7976931348623159E308;
  ENDPROC
ENDMODULE
