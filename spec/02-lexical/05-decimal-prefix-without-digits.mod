MODULE decimal_prefix_without_digits
! @section 2.5
! @expect lexical-error 7:10
! @description 0D without digits is not a decimal integer: the literal 0 touches the identifier D.
  VAR num x;
  PROC main()
    x := 0D;
  ENDPROC
ENDMODULE
