MODULE alias_of_builtin_alias
! @format 2
! @section 2.15
! @expect semantic-error 6:9
! @description errnum is a built-in alias of num, so an alias of errnum is an alias of an alias; refused at errnum.
  ALIAS errnum fault_code;
ENDMODULE
