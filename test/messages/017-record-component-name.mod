MODULE t
! @expect-message 4:8: syntax error: expected the component's name after its data type (§2.14); found ';'
  RECORD r
    num;
  ENDRECORD
ENDMODULE
