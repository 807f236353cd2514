MODULE assignment_component_type
! @format 2
! @section 4.5
! @expect semantic-error 8:12
! @description The component x of a pos is a num; a string is refused at the right-hand side.
  VAR pos p;
  PROC main()
    p.x := "a";
  ENDPROC
ENDMODULE
