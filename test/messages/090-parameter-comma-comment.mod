MODULE t
! @expect-message 3:17: syntax error: expected a parameter declaration, '\' or <PAR> after ',' (§5.2); comments are list elements only (§2.10); found a comment
  PROC p(num a, ! first
         num b)
  ENDPROC
ENDMODULE
