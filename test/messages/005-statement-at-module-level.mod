MODULE t
! @expect-message 3:3: syntax error: expected a type definition, a data declaration (VAR, PERS or CONST, after an optional LOCAL or TASK), a routine declaration or ENDMODULE (§9.2, §2.18); found WHILE
  WHILE TRUE DO
  ENDWHILE
ENDMODULE
