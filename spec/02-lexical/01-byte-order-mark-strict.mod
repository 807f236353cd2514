MODULE byte_order_mark_strict
! @section 2.1
! @expect lexical-error 1:1
! @options strict
! @description In strict mode a byte-order mark is refused: U+FEFF is not a character of ISO 8859-1.
  VAR num x;
  PROC main()
    x := 1;
  ENDPROC
ENDMODULE
