MODULE function_called_as_procedure
! @format 2
! @section 4.6
! @expect semantic-error 7:5
! @description A function is called in expressions only; a procedure call naming it is refused at the name.
  PROC main()
    twice 1;
  ENDPROC
  FUNC num twice(num x)
    RETURN 2 * x;
  ENDFUNC
ENDMODULE
