MODULE t
! @expect-message 3:19: syntax error: expected an expression after '[': an aggregate has at least one member (§3.10); comments are list elements only (§2.10); found ']'
  CONST pos p := [];
ENDMODULE
