MODULE pose_nested_aggregate
! @format 2
! @section 2.17
! @section 3.10
! @expect ok
! @description A pose aggregate of a pos aggregate and an orient object (section 2.14's p1 := [[100, 100, 0], o1]).
  VAR pose p1;
  VAR orient o1;
  VAR pose frame := [[100, 100, 0], [1, 0, 0, 0]];
  PROC main()
    p1 := [[100, 100, 0], o1];
  ENDPROC
ENDMODULE
