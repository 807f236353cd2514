MODULE goto_statement
! @section 4.7
! @expect ok
! @description The example of section 4.7: <goto statement> ::= GOTO <identifier> ';'.
  VAR num i;
  PROC main()
    next:
    i := i + 1;
    GOTO next;
    GOTO <ID>;
  ENDPROC
ENDMODULE
