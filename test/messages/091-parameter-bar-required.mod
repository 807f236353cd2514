MODULE t
! @expect-message 3:16: syntax error: expected ',', '\' or ')' after the parameter; '|' only separates the alternatives of an optional parameter (§5.2); found '|'
  PROC p(num a | num b)
  ENDPROC
ENDMODULE
