MODULE exponent_without_digits
! @section 2.5
! @expect lexical-error 7:10
! @description An exponent needs digits: 1E is the literal 1 touching the identifier E.
  VAR num x;
  PROC main()
    x := 1E;
  ENDPROC
ENDMODULE
