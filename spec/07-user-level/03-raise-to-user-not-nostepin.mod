MODULE raise_to_user_not_nostepin
! @format 2
! @section 7.3
! @section 9.4
! @expect semantic-error 10:5
! @description RaiseToUser in the error handler of a routine of a module without NOSTEPIN is refused: that routine is at the user level itself (section 7.3: the user level is the first routine above the nostepin ones; doc/rulings.md R-7.3-n).
  PROC tool()
    RAISE 5;
  ERROR
    RaiseToUser \BreakOff;
  ENDPROC
ENDMODULE
