MODULE t
! @expect-message 5:3: syntax error: expected a statement, ERROR, UNDO or ENDFUNC (§5.5); BACKWARD belongs to procedures only (§5.4); found ENDPROC
  FUNC num f()
    RETURN 1;
  ENDPROC
ENDMODULE
