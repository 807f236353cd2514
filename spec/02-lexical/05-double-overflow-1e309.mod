MODULE double_overflow_1e309
! @section 2.5
! @expect lexical-error 7:10
! @description 1E309 is out of the range of IEEE 754 double precision.
  VAR dnum x;
  PROC main()
    x := 1E309;
  ENDPROC
ENDMODULE
