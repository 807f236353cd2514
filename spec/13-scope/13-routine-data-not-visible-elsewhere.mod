MODULE routine_data_not_visible
! @format 2
! @section 13
! @section 2.20
! @expect semantic-error 12:5
! @description The scope of a routine data object is its routine: another routine of the module does not see it.
  PROC main()
    VAR num work;
    work := 1;
  ENDPROC
  PROC helper()
    work := 2;
  ENDPROC
ENDMODULE
