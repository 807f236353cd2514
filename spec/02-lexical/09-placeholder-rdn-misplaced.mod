MODULE placeholder_rdn_misplaced
! @section 2.9
! @expect syntax-error 6:5
! @description <RDN> is a routine declaration: routines do not nest.
  PROC main()
    <RDN>
  ENDPROC
ENDMODULE
