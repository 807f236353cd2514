MODULE op_mode_rob_os
! @format 3
! @section 13
! @expect ok
! @description OpMode (ABB's RAPID reference, OpMode: the operating mode, a symnum compared with OP_UNDEF, OP_AUTO, OP_MAN_PROG, OP_MAN_TEST) is OP_AUTO in rapid-sem, which runs a program with nobody at the FlexPendant; RobOS (ABB: TRUE on a robot controller, FALSE on a virtual one) is FALSE (doc/rulings.md R-13-sys2).
! @output automatic
! @output virtual controller
  PROC main()
    TEST OpMode()
    CASE OP_AUTO:
      TPWrite "automatic";
    CASE OP_MAN_PROG, OP_MAN_TEST:
      TPWrite "manual";
    DEFAULT:
      TPWrite "undefined";
    ENDTEST
    IF RobOS() THEN
      TPWrite "robot controller";
    ELSE
      TPWrite "virtual controller";
    ENDIF
  ENDPROC
ENDMODULE
