MODULE t
! @expect-message 6:5: syntax error: expected ';' after the record component (§2.14); found the identifier num
! @expect-hint ';' is missing at the end of line 5: a simple statement and a declaration end with ';' (§4.3, §2.18)
  RECORD r
    num a
    num b;
  ENDRECORD
ENDMODULE
