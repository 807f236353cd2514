MODULE assignment_to_constant_component
! @format 2
! @section 4.5
! @expect semantic-error 8:5
! @description A component of a constant record is no assignment target; refused at the start of the target.
  CONST pos origin := [0, 0, 0];
  PROC main()
    origin.x := 1;
  ENDPROC
ENDMODULE
