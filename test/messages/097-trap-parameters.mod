MODULE t
! @expect-message 3:9: syntax error: expected the trap routine's data declarations and statements, or ENDTRAP: a trap routine has no parameter list (§5.6); found '('
  TRAP t()
  ENDTRAP
ENDMODULE
