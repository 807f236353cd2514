MODULE parameter_declaration_ref
! @section 5.2
! @section 11
! @expect syntax-error 6:18
! @description REF is no access mode of the grammar (RAPID routines cannot have ref parameters): REF num reads as type REF, name num.
  PROC p(REF num a)
  ENDPROC
ENDMODULE
