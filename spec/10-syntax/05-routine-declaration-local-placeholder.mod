MODULE routine_declaration_local_placeh
! @section 5.1
! @expect syntax-error 5:9
! @description LOCAL applies to a routine declaration, not to the <RDN> placeholder.
  LOCAL <RDN>
ENDMODULE
