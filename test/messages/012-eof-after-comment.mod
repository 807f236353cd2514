MODULE t
! @expect-message 4:1: syntax error: after the comment expected a declaration, a statement, or the keyword that ends the routine or module (§2.10); found the end of the file
  ! nothing else
