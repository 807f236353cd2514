MODULE function_argument_conditional_li
! @section 3.11
! @expect syntax-error 7:17
! @description <conditional function argument> ::= '\' <ident> '?' <parameter>: a literal is not a parameter.
  VAR num x;
  PROC main()
    x := f(\a ? 1);
  ENDPROC
ENDMODULE
