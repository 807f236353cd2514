MODULE t
! @expect-message 5:1: syntax error: expected another record component or ENDRECORD (§2.14); found ENDMODULE
  RECORD r
    num a;
ENDMODULE
