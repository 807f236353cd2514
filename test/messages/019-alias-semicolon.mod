MODULE t
! @expect-message 4:1: syntax error: expected ';' to end the alias definition (§2.15); found ENDMODULE
  ALIAS num length
ENDMODULE
