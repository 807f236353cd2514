MODULE procedure_call_forms
! @format 2
! @section 4.6
! @expect ok
! @description The procedure calls of section 4.6: positional, by name, with a switch, with the mutually exclusive optional arguments speed or time.
  VAR string t1 := "gripper";
  VAR pos pos2;
  VAR pos dest;
  VAR num mv := 1;

  PROC main()
    move t1, pos2, mv;
    move tool := t1, dest := pos2, movedata := mv;
    move \reltool, t1, dest, mv;
    move \reltool, t1, dest, mv \speed := 100;
    move \reltool, t1, dest, mv \time := 20;
  ENDPROC

  PROC move(\switch reltool, string tool, pos dest, num movedata \num speed | num time)
  ENDPROC
ENDMODULE
