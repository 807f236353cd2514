MODULE t
! @expect-message 5:1: syntax error: after the comment expected a declaration, a statement, or the keyword that ends the routine or module (§2.10); found the end of the file
! @expect-hint the MODULE t at line 1 is not closed: ENDMODULE is missing (§9.2)
  ! nothing else
