MODULE assignment_to_constant_element
! @format 2
! @section 4.5
! @expect semantic-error 8:5
! @description An element of a constant array is no assignment target; refused at the start of the target.
  CONST num limits{2} := [1, 2];
  PROC main()
    limits{1} := 3;
  ENDPROC
ENDMODULE
