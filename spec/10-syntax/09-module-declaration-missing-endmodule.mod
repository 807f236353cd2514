MODULE module_declaration_missing_endmo
! @section 9.2
! @expect syntax-error 7:1
! @description ENDMODULE may not be left out: the end of the file comes first (reported just after the last line break).
  PROC main()
  ENDPROC
