MODULE loadidentify_not_modelled
! @format 3
! @section 11
! @expect ok
! @description LoadIdentify (ABB's service routine identifying a load by moving the robot and asking the operator) is installed, so a program calling it checks; it is not modelled (exit 4) at the call (doc/rulings.md R-13-motset1).
! @exit 4
! @error LoadIdentify 9:5
  PROC main()
    LoadIdentify;
  ENDPROC
ENDMODULE
