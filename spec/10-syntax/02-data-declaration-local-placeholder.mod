MODULE data_declaration_local_placehold
! @section 2.18
! @expect syntax-error 5:9
! @description LOCAL applies to a declaration, not to the <DDN> placeholder.
  LOCAL <DDN>
ENDMODULE
