MODULE label
! @section 4.4
! @expect ok
! @description The example of sections 4.4 and 4.7, and <ID> as a label: <label> ::= <identifier> ':'.
  VAR num i;
  PROC main()
    next:
    i := i + 1;
    IF i < 10 GOTO next;
    <ID>:
  ENDPROC
ENDMODULE
