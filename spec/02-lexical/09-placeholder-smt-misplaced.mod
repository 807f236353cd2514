MODULE placeholder_smt_misplaced
! @section 2.9
! @expect syntax-error 5:3
! @description <SMT> is a statement: statements stand only inside routines.
  <SMT>
ENDMODULE
