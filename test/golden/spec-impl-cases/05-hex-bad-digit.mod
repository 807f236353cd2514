MODULE hex_bad_digit
! @section 2.5
! @expect lexical-error 7:10
! @description G is not a hex digit: the literal 0x1 touches the identifier G.
  VAR num x;
  PROC main()
    x := 0x1G;
  ENDPROC
ENDMODULE
