MODULE function_argument_optional_place
! @section 3.11
! @expect syntax-error 7:13
! @description <optional function argument> ::= '\' <ident> [...]: <ident>, not <identifier>, so <ID> is refused.
  VAR num x;
  PROC main()
    x := f(\<ID>);
  ENDPROC
ENDMODULE
