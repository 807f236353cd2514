MODULE t
! @expect-message 5:3: syntax error: expected ';' after EXIT (§4.12, §4.2); found ENDPROC
  PROC main()
    EXIT
  ENDPROC
ENDMODULE
