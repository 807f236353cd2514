MODULE optional_argument_unknown
! @format 2
! @section 4.6
! @expect semantic-error 12:23
! @description An optional argument must name an optional parameter; refused at the backslash.
  VAR string t1 := "gripper";
  VAR pos pos2;
  VAR pos dest;
  VAR num mv := 1;

  PROC main()
    move t1, pos2, mv \velocity := 3;
  ENDPROC

  PROC move(\switch reltool, string tool, pos dest, num movedata \num speed | num time)
  ENDPROC
ENDMODULE
