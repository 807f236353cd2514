MODULE t
! @expect-message 4:3: syntax error: expected an operator, or what follows the expression such as ';', ')', THEN or DO (§3.1); comments are list elements only (§2.10); found PERS
  PERS num count := 0
  PERS num total := 0;
ENDMODULE
