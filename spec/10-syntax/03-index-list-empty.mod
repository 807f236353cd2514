MODULE index_list_empty
! @section 3.6
! @expect syntax-error 8:12
! @description <index list> ::= <expr> { , <expr> } holds at least one index.
  VAR num x;
  VAR num a{2};
  PROC main()
    x := a{};
  ENDPROC
ENDMODULE
