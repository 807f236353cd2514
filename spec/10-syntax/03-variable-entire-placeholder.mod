MODULE variable_entire_placeholder
! @section 3.6
! @expect syntax-error 7:14
! @description <entire variable> ::= <ident>: <ID> can only be a function name here, so a component cannot follow it.
  VAR num x;
  PROC main()
    x := <ID>.y;
  ENDPROC
ENDMODULE
