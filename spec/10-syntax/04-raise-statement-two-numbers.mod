MODULE raise_statement_two_numbers
! @section 4.11
! @expect syntax-error 6:12
! @description <raise statement> ::= RAISE [ <error number> ] ';' with one error number.
  PROC p()
    RAISE 1, 2;
  ENDPROC
ENDMODULE
