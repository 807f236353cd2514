MODULE variable_declaration_missing_sem
! @section 2.22
! @expect syntax-error 6:3
! @description A variable declaration ends with ';'.
  VAR num x := 1
  VAR num y;
ENDMODULE
