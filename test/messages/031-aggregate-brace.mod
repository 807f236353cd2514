MODULE t
! @expect-message 3:26: syntax error: expected ']' to close the aggregate (§3.10); found '}'
  CONST pos p := [1, 2, 3};
ENDMODULE
