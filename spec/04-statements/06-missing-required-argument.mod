MODULE missing_required_argument
! @format 2
! @section 4.6
! @expect semantic-error 12:5
! @description A required argument may not be left out of a procedure call; refused at the procedure name.
  VAR string t1 := "gripper";
  VAR pos pos2;
  VAR pos dest;
  VAR num mv := 1;

  PROC main()
    move t1, pos2;
  ENDPROC

  PROC move(\switch reltool, string tool, pos dest, num movedata \num speed | num time)
  ENDPROC
ENDMODULE
