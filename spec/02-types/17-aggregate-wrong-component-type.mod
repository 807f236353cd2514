MODULE aggregate_wrong_component_type
! @format 2
! @section 2.17
! @section 3.10
! @expect semantic-error 9:14
! @description An aggregate member of type string for a num component; refused at the member that does not fit.
  VAR pos p;
  PROC main()
    p := [1, "two", 3];
  ENDPROC
ENDMODULE
