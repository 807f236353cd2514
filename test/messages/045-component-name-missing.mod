MODULE t
! @expect-message 4:12: syntax error: expected a component name after '.' (§3.6); found ';'
  PROC main()
    x := p.;
  ENDPROC
ENDMODULE
