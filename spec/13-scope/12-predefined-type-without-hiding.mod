MODULE predefined_type_without_hiding
! @format 2
! @section 2.12
! @section 2.17
! @expect semantic-error 7:28
! @description Without a module type of that name, intnum is the predefined alias of num: a string initialiser is refused.
  VAR intnum label_text := "abc";
ENDMODULE
