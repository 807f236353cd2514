MODULE t
! @expect-message 4:10: syntax error: expected ':' for a label, or the arguments or ';' of a procedure call, after <ID>; <ID> cannot be an assignment target (§3.6, §4.4, §4.6); found ':='
  PROC main()
    <ID> := 1;
  ENDPROC
ENDMODULE
