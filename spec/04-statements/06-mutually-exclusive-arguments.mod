MODULE mutually_exclusive_arguments
! @format 2
! @section 4.6
! @expect semantic-error 12:37
! @description speed and time are mutually exclusive; the second is refused at its backslash.
  VAR string t1 := "gripper";
  VAR pos pos2;
  VAR pos dest;
  VAR num mv := 1;

  PROC main()
    move t1, pos2, mv \speed := 100 \time := 20;
  ENDPROC

  PROC move(\switch reltool, string tool, pos dest, num movedata \num speed | num time)
  ENDPROC
ENDMODULE
