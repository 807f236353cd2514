MODULE type_definition_local_placeholde
! @section 2.11
! @expect syntax-error 5:9
! @description LOCAL applies to a record or alias definition, not to the <TDN> placeholder.
  LOCAL <TDN>
ENDMODULE
