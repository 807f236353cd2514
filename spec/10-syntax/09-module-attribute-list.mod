MODULE module_attribute_list (SYSMODULE, NOVIEW)
! @section 9.2
! @expect ok
! @description <module attribute list> ::= '(' <module attribute> { ',' <module attribute> } ')'.
ENDMODULE
