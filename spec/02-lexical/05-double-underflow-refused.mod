MODULE double_underflow_refused
! @section 2.5
! @expect lexical-error 7:10
! @description A nonzero literal that rounds to zero in double precision is out of range.
  VAR dnum x;
  PROC main()
    x := 2.4E-324;
  ENDPROC
ENDMODULE
