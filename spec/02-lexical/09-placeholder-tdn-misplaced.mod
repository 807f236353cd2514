MODULE placeholder_tdn_misplaced
! @section 2.9
! @expect syntax-error 6:5
! @description <TDN> is a type definition, not a statement.
  PROC main()
    <TDN>
  ENDPROC
ENDMODULE
