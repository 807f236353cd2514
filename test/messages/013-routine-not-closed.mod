MODULE t
! @expect-message 5:3: syntax error: the routine is not closed: expected a data declaration, a statement, or ENDPROC, ENDFUNC or ENDTRAP (§5.4, §5.5, §5.6); found PROC
  PROC a()
    ! empty
  PROC b()
  ENDPROC
ENDMODULE
