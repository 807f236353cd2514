MODULE variable_element_of_component
! @section 3.6
! @expect syntax-error 7:13
! @description <variable element> ::= <entire variable> { <index list> }: a component cannot be indexed.
  VAR num x;
  PROC main()
    x := a.b{1};
  ENDPROC
ENDMODULE
