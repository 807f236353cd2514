MODULE constant_component_of_element_in
! @section 3.8
! @expect syntax-error 8:14
! @description A component name follows '.', not an index list.
  CONST pos seq{2} := [[1, 2, 3], [4, 5, 6]];
  VAR num x;
  PROC main()
    x := seq.{1};
  ENDPROC
ENDMODULE
