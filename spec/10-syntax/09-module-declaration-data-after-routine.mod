MODULE module_declaration_data_after_ro
! @section 9.2
! @expect syntax-error 7:3
! @description The data declaration list precedes the routine declaration list.
  PROC main()
  ENDPROC
  VAR num x;
ENDMODULE
