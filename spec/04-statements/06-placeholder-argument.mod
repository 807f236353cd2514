MODULE placeholder_argument
! @format 2
! @section 4.6
! @section 2.9
! @expect ok
! @description <ARG> stands for an undefined argument without a semantic error.
  VAR string t1 := "gripper";
  VAR pos pos2;
  VAR pos dest;
  VAR num mv := 1;

  PROC main()
    move t1, <ARG>, mv;
  ENDPROC

  PROC move(\switch reltool, string tool, pos dest, num movedata \num speed | num time)
  ENDPROC
ENDMODULE
