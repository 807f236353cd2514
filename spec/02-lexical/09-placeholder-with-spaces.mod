MODULE placeholder_with_spaces
! @section 2.9
! @expect syntax-error 6:5
! @description A placeholder is one token: "< SMT >" is "<", an identifier and ">".
  PROC main()
    < SMT >
  ENDPROC
ENDMODULE
