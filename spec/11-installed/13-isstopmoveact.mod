MODULE is_stop_move_act
! @format 3
! @section 13
! @expect ok
! @description IsStopMoveAct tells whether a StopMove of the motion task is in force: FALSE before it, TRUE after it until StartMove; with \FromNonMoveTask always FALSE, since only the motion task can stop its robot; without a switch, a stop from either (doc/rulings.md R-13-z, R-14-e).
! @output start FALSE FALSE
! @output stopped TRUE FALSE
! @output either TRUE
! @output started FALSE
  PROC main()
    Show "start";
    StopMove;
    Show "stopped";
    TPWrite "either " + ValToStr(IsStopMoveAct());
    ClearPath;
    StartMove;
    TPWrite "started " + ValToStr(IsStopMoveAct(\FromMoveTask));
  ENDPROC
  PROC Show(string what)
    TPWrite what + " " + ValToStr(IsStopMoveAct(\FromMoveTask)) + " " + ValToStr(IsStopMoveAct(\FromNonMoveTask));
  ENDPROC
ENDMODULE
