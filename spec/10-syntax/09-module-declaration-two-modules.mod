MODULE module_declaration_two_modules
! @section 9.2
! @expect syntax-error 6:1
! @description A file holds one module.
ENDMODULE
MODULE second
ENDMODULE
