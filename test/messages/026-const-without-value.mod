MODULE t
! @expect-message 3:18: syntax error: expected '{' and the dimensions, or ':=' and the value: a constant declaration has a value (§2.24); found ';'
  CONST num limit;
ENDMODULE
