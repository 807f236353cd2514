MODULE parameter_not_visible_elsewhere
! @format 2
! @section 13
! @section 5.3
! @expect semantic-error 11:10
! @description The scope of a parameter is its routine; refused at the name in another routine.
  VAR num n;
  PROC set_speed(num speed)
  ENDPROC
  PROC main()
    n := speed;
  ENDPROC
ENDMODULE
