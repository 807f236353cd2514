MODULE getmotortorque_not_modelled
! @format 3
! @section 11
! @expect ok
! @description GetMotorTorque (ABB, RobotWare 6) is installed, so a program calling it checks; the motion model has no dynamics, so running it is "not modelled" (exit 4) at the call, not an unknown function.
! @exit 4
! @error GetMotorTorque 10:10
  PROC main()
    VAR num t := 0;
    t := GetMotorTorque(2);
  ENDPROC
ENDMODULE
