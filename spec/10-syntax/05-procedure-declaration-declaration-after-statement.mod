MODULE procedure_declaration_declaratio
! @section 5.4
! @expect syntax-error 8:5
! @description The data declaration list of a routine precedes its statement list.
  PROC p()
    VAR num x;
    x := 1;
    VAR num y;
  ENDPROC
ENDMODULE
