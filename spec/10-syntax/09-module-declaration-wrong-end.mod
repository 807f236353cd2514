MODULE module_declaration_wrong_end
! @section 9.2
! @expect syntax-error 5:1
! @description A module is closed by ENDMODULE.
ENDPROC
