MODULE reserved_word_lower_case_refused
! @section 2.3
! @section 2.4
! @expect syntax-error 6:11
! @description "while" is the reserved word WHILE in lower case and cannot be an identifier.
  VAR num while;
ENDMODULE
