MODULE assignment_to_intno
! @format 2
! @section 4.5
! @section 12
! @expect semantic-error 8:5
! @description INTNO is read-only, updated only by the system (chapter 12); refused at the target.
  TRAP on_event
    INTNO := 0;
  ENDTRAP
ENDMODULE
