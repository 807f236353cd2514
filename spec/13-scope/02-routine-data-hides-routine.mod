MODULE routine_data_hides_routine
! @format 2
! @section 2.20
! @section 5.3
! @expect ok
! @description A routine data object hides a routine of the same name within its routine.
  PROC main()
    VAR num helper;
    helper := 1;
  ENDPROC
  PROC helper()
  ENDPROC
ENDMODULE
