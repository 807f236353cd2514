MODULE module_attributes_each(SYSMODULE, NOSTEPIN, READONLY)
! @section 9.2
! @expect ok
! @description SYSMODULE, NOSTEPIN and READONLY in the order of the attribute table.
ENDMODULE
