MODULE data_type_reserved_word
! @section 2.11
! @expect syntax-error 5:7
! @description <data type> ::= <identifier>: a reserved word is not one.
  VAR RECORD x;
ENDMODULE
