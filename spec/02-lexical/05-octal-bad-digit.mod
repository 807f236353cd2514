MODULE octal_bad_digit
! @section 2.5
! @expect lexical-error 7:10
! @description 9 is not an octal digit: the literal 0O1 touches the literal 9.
  VAR num x;
  PROC main()
    x := 0O19;
  ENDPROC
ENDMODULE
