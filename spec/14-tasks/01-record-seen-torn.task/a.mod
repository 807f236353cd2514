MODULE torn_a
! @format 4
! @task T_ROB1
! @section 14
! @expect ok
! @description ch. 14: a record assigned component by component is read inconsistent by another task between the assignments. Turns are of one statement, round robin (R-14-a): B reads p after A's first component assignment.
! @output B read [1,0,0]
! @output A done [1,1,1]
  PERS pos p := [0, 0, 0];
  PROC main()
    p.x := 1;
    p.y := 1;
    p.z := 1;
    TPWrite "A done " \Pos := p;
  ENDPROC
ENDMODULE
