MODULE late_binding_function_name
! @format 3
! @section 4.6
! @section 12
! @expect ok
! @description Late binding is for procedure calls only (section 4.6): a name that denotes a function raises ERR_CALLPROC, chapter 12's "procedure call error at run time (syntax, not a procedure)" (reading: ERR_REFUNKPRC is kept for names that denote nothing).
! @exit 1
! @error ERR_CALLPROC 13:5
  FUNC num answer()
    RETURN 42;
  ENDFUNC
  PROC main()
    % "answer" %;
  ENDPROC
ENDMODULE
