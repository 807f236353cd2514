MODULE module_attributes_viewonly (VIEWONLY)
! @section 9.2
! @expect ok
! @description VIEWONLY alone.
ENDMODULE
