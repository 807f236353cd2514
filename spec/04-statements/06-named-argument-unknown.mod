MODULE named_argument_unknown
! @format 2
! @section 4.6
! @expect semantic-error 12:52
! @description A named argument must name a parameter (speed is optional and takes a backslash); refused at the argument.
  VAR string t1 := "gripper";
  VAR pos pos2;
  VAR pos dest;
  VAR num mv := 1;

  PROC main()
    move tool := t1, dest := pos2, movedata := mv, speeed := 100;
  ENDPROC

  PROC move(\switch reltool, string tool, pos dest, num movedata \num speed | num time)
  ENDPROC
ENDMODULE
