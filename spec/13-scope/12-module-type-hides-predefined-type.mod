MODULE module_type_hides_predefined
! @format 2
! @section 2.12
! @expect ok
! @description A module type definition hides a predefined type of the same name: intnum is an alias of string here.
  ALIAS string intnum;
  VAR intnum label_text := "abc";
ENDMODULE
