MODULE argument_type
! @format 2
! @section 4.6
! @expect semantic-error 12:10
! @description An argument's type must equal its parameter's: a num for tool (string) is refused at the argument.
  VAR string t1 := "gripper";
  VAR pos pos2;
  VAR pos dest;
  VAR num mv := 1;

  PROC main()
    move mv, pos2, mv;
  ENDPROC

  PROC move(\switch reltool, string tool, pos dest, num movedata \num speed | num time)
  ENDPROC
ENDMODULE
