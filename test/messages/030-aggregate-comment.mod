MODULE t
! @expect-message 3:22: syntax error: expected an expression after ',' (§3.6, §3.10); comments are list elements only (§2.10); found a comment
  CONST pos p := [1, ! x
                  2, 3];
ENDMODULE
