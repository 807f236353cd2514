MODULE t
! @expect-message 5:5: syntax error: expected ';' after the record component (§2.14); found the identifier num
  RECORD r
    num a
    num b;
  ENDRECORD
ENDMODULE
