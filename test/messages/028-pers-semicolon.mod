MODULE t
! @expect-message 5:3: syntax error: expected an operator, or what follows the expression such as ';', ')', THEN or DO (§3.1); comments are list elements only (§2.10); found PERS
! @expect-hint ';' is missing at the end of line 4: a simple statement and a declaration end with ';' (§4.3, §2.18)
  PERS num count := 0
  PERS num total := 0;
ENDMODULE
