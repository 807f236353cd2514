MODULE t
! @expect-message 3:12: syntax error: expected the function's name after its data type (§5.5); found '('
  FUNC num (num x)
    RETURN x;
  ENDFUNC
ENDMODULE
