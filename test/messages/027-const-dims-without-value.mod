MODULE t
! @expect-message 3:22: syntax error: expected ':=' and the value after the dimensions: a constant declaration has a value (§2.24); found ';'
  CONST num limits{2};
ENDMODULE
