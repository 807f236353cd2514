MODULE connect_target_literal
! @section 4.15
! @expect syntax-error 6:13
! @description <connect target> ::= <variable> | <parameter> | <VAR>: a literal is none of them.
  PROC main()
    CONNECT 1 WITH high_pressure;
  ENDPROC
ENDMODULE
