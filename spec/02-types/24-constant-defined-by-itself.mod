MODULE constant_defined_by_itself
! @format 2
! @section 3.2
! @section 2.24
! @expect semantic-error 7:18
! @description A constant represents a static value (§2.24) given by a constant expression (§3.2); one whose value depends on itself has none. Refused at the reference that closes the cycle.
  CONST num a := a + 1;
  PROC main()
  ENDPROC
ENDMODULE
