MODULE t
! @expect-message 3:7: syntax error: expected a data type after VAR (§2.22); found ':='
  VAR := 1;
ENDMODULE
