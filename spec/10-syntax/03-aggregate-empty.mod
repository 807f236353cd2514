MODULE aggregate_empty
! @section 3.10
! @expect syntax-error 7:11
! @description <aggregate> ::= '[' <expr> { ',' <expr> } ']' holds at least one element.
  VAR pos p;
  PROC main()
    p := [];
  ENDPROC
ENDMODULE
