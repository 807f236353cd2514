MODULE procedure_argument_conditional_l
! @section 4.6
! @expect syntax-error 6:12
! @description <conditional procedure argument> ::= '\' <identifier> '?' ( <parameter> | <VAR> ): a literal is neither.
  PROC main()
    p \a ? 1;
  ENDPROC
ENDMODULE
