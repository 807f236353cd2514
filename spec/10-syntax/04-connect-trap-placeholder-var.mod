MODULE connect_trap_placeholder_var
! @section 4.15
! @expect syntax-error 7:21
! @description <trap> ::= <identifier>: <VAR> is not one.
  VAR intnum hp;
  PROC main()
    CONNECT hp WITH <VAR>;
  ENDPROC
ENDMODULE
