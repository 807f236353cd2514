MODULE t
! @expect-message 3:3: syntax error: expected a type definition, data declaration, routine declaration or ENDMODULE (§9.2); found WHILE
  WHILE TRUE DO
  ENDWHILE
ENDMODULE
