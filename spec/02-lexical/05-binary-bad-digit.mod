MODULE binary_bad_digit
! @section 2.5
! @expect lexical-error 7:10
! @description 2 is not a binary digit: the literal 0B10 touches the literal 2.
  VAR num x;
  PROC main()
    x := 0B102;
  ENDPROC
ENDMODULE
