MODULE raise_to_user_without_switch (NOSTEPIN)
! @format 2
! @section 7.3
! @expect semantic-error 9:5
! @description RaiseToUser needs one of \Continue (\Resume) and \BreakOff: whether the NOSTEPIN routines go on after the user's handler or are broken off (ABB's RaiseToUser: one of the two is mandatory; doc/rulings.md R-7.3-n).
  PROC tool()
    RAISE 5;
  ERROR
    RaiseToUser \ErrorNumber:=6;
  ENDPROC
ENDMODULE
