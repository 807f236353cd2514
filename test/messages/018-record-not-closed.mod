MODULE t
! @expect-message 6:1: syntax error: expected another record component or ENDRECORD (§2.14); found ENDMODULE
! @expect-hint the RECORD r at line 4 is not closed: ENDRECORD is missing before this ENDMODULE (§2.14)
  RECORD r
    num a;
ENDMODULE
