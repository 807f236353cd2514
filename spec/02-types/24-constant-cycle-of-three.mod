MODULE constant_cycle_of_three
! @format 2
! @section 3.2
! @section 2.24
! @expect semantic-error 8:22
! @description Three constants in a cycle, through a component of a record constant and an array element. Refused at the p in the initial value of v: evaluated in declaration order, that reference closes the cycle.
  CONST pos p := [c, 0, 0];
  CONST num v{2} := [p.x, 1];
  CONST num c := 1 + v{1};
  PROC main()
  ENDPROC
ENDMODULE
