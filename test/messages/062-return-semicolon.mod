MODULE t
! @expect-message 5:3: syntax error: expected an expression or ';' after RETURN (§4.10); found ENDPROC
  PROC main()
    RETURN
  ENDPROC
ENDMODULE
