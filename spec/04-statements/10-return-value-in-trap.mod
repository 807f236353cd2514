MODULE return_value_in_trap
! @format 2
! @section 4.10
! @expect semantic-error 7:5
! @description A RETURN in a trap routine may not have a return expression; refused at RETURN.
  TRAP on_event
    RETURN TRUE;
  ENDTRAP
ENDMODULE
