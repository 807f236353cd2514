MODULE t
! @expect-message 3:16: syntax error: expected '*' or <DIM> after '{': an array parameter's dimensions are written '*' (§5.2); found the numeric literal 3
  PROC p(num a{3})
  ENDPROC
ENDMODULE
