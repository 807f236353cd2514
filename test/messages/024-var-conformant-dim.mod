MODULE t
! @expect-message 3:13: syntax error: expected a dimension, a constant expression, after '{' (§2.22); '*' is allowed only in parameter declarations (§5.2); found '*'
  VAR num a{*};
ENDMODULE
