MODULE speedlim_arguments
! @format 2
! @section 4.6
! @section 13
! @expect semantic-error 9:24
! @description SpeedLimCheckPoint RobSpeed (ABB, RAPID Instructions) takes a num: a string is refused at the argument.
  PROC main()
    SpeedLimAxis ROB_1, 2, 45;
    SpeedLimCheckPoint "fast";
  ENDPROC
ENDMODULE
