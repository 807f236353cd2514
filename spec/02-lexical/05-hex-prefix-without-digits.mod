MODULE hex_prefix_without_digits
! @section 2.5
! @expect lexical-error 7:10
! @description 0X without hex digits is not a hex literal: the literal 0 touches the identifier X.
  VAR num x;
  PROC main()
    x := 0X;
  ENDPROC
ENDMODULE
