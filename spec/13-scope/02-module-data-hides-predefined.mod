MODULE module_data_hides_predefined
! @format 2
! @section 2.20
! @section 2.19
! @expect ok
! @description A module data object hides a predefined object of the same name: ERR_NOTPRES is a string here.
  CONST string ERR_NOTPRES := "absent";
  PROC main()
    TPWrite ERR_NOTPRES;
  ENDPROC
ENDMODULE
