MODULE procedure_declaration_arrmul
! @section 5.4
! @expect ok
! @description The example of section 5.4, its comment right after ENDPROC.
  PROC arrmul( VAR num array{*}, num factor)
    FOR index FROM 1 TO Dim( array, 1 ) DO
      array{index} := array{index} * factor;
    ENDFOR
  ENDPROC! implicit return
ENDMODULE
