MODULE persistent_declaration_empty_ini
! @section 2.23
! @expect syntax-error 5:17
! @description After ':=' a persistent declaration needs a literal expression.
  PERS num x := ;
ENDMODULE
