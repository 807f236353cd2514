MODULE t
! @expect-message 3:15: syntax error: expected an operator, or what follows the expression such as ';', ')', THEN or DO (§3.1); comments are list elements only (§2.10); found the numeric literal 3
  VAR num a{2 3};
ENDMODULE
