MODULE main_without_parameters
! @format 2
! @section 9.1
! @expect ok
! @description The entry routine main has no parameters.
  VAR num n;
  PROC main()
    n := 1;
  ENDPROC
ENDMODULE
