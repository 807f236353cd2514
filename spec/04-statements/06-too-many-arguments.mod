MODULE too_many_arguments
! @format 2
! @section 4.6
! @expect semantic-error 12:24
! @description A procedure call with more required arguments than parameters; refused at the first argument too many.
  VAR string t1 := "gripper";
  VAR pos pos2;
  VAR pos dest;
  VAR num mv := 1;

  PROC main()
    move t1, pos2, mv, mv;
  ENDPROC

  PROC move(\switch reltool, string tool, pos dest, num movedata \num speed | num time)
  ENDPROC
ENDMODULE
