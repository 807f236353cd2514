MODULE module_attribute_list_missing_co (SYSMODULE NOSTEPIN)
! @section 9.2
! @expect syntax-error 1:52
! @description Module attributes are separated by ','.
ENDMODULE
