MODULE letter_case_clash
! @format 2
! @section 2.20
! @section 2.3
! @expect semantic-error 8:11
! @description Identifiers differing only in letter case are the same identifier; the second declaration is refused at its name.
  VAR num Counter;
  VAR num COUNTER;
ENDMODULE
