MODULE module_attribute_list_empty ()
! @section 9.2
! @expect syntax-error 1:37
! @description A module attribute list holds at least one attribute.
ENDMODULE
