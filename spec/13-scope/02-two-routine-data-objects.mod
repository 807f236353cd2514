MODULE two_routine_data_objects
! @format 2
! @section 2.20
! @expect semantic-error 8:16
! @description Two routine data objects declared in the same routine may not have the same name; the second is refused at its name.
  PROC main()
    VAR num count;
    VAR string count;
  ENDPROC
ENDMODULE
