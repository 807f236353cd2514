MODULE t
! @expect-message 6:3: syntax error: expected a statement, ERROR, UNDO or ENDFUNC (§5.5); BACKWARD belongs to procedures only (§5.4); found ENDPROC
! @expect-hint ENDPROC closes no open construct here; the FUNC f at line 4 is closed by ENDFUNC (§5.5)
  FUNC num f()
    RETURN 1;
  ENDPROC
ENDMODULE
