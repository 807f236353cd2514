MODULE t
! @expect-message 6:3: syntax error: the routine is not closed: expected a data declaration, a statement, or ENDPROC, ENDFUNC or ENDTRAP (§5.4, §5.5, §5.6); found PROC
! @expect-hint the PROC a at line 4 is not closed: ENDPROC is missing (§5.4)
  PROC a()
    ! empty
  PROC b()
  ENDPROC
ENDMODULE
