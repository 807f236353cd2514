MODULE raise_to_user_outside_handler (NOSTEPIN)
! @format 2
! @section 7.3
! @expect semantic-error 7:5
! @description RaiseToUser hands the error in hand to the user level: it may stand only in an error handler of a routine of a NOSTEPIN module (ABB's RaiseToUser; doc/rulings.md R-7.3-n), not in a routine's body.
  PROC tool()
    RaiseToUser \BreakOff;
  ENDPROC
ENDMODULE
