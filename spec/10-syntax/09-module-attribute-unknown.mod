MODULE module_attribute_unknown (SHARED)
! @section 9.2
! @expect syntax-error 1:34
! @description <module attribute> ::= SYSMODULE | NOVIEW | NOSTEPIN | VIEWONLY | READONLY.
ENDMODULE
