MODULE t
! @expect-message 3:12: syntax error: expected the name of the new data type after the aliased type (§2.15); found ';'
  ALIAS num;
ENDMODULE
