MODULE t
! @expect-message 5:1: syntax error: expected ';' to end the alias definition (§2.15); found ENDMODULE
! @expect-hint ';' is missing at the end of line 4: a simple statement and a declaration end with ';' (§4.3, §2.18)
  ALIAS num length
ENDMODULE
