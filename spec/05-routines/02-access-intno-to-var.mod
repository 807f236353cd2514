MODULE access_intno_to_var
! @format 2
! @section 5.2
! @section 11
! @section 12
! @expect semantic-error 9:12
! @description Table of section 5.2, row read-only variable (INTNO), column var: IWatch's parameter is VAR intnum; refused at the argument.
  TRAP on_event
    IWatch INTNO;
  ENDTRAP
ENDMODULE
