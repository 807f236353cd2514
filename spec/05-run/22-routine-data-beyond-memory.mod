MODULE routine_data_beyond_memory
! @format 3
! @section 2.22
! @section 1.4
! @expect ok
! @description Routine data is created at each call (section 2.21); an array of a thousand million elements is beyond any system's resources (section 1.4: a fatal error caused by a system resource), and the run ends as a limit exhausted, before the routine runs.
! @output before
! @exit 3
  PROC huge()
    VAR num matrix{1000, 1000, 1000};
    TPWrite "inside";
  ENDPROC
  PROC main()
    TPWrite "before";
    huge;
    TPWrite "after";
  ENDPROC
ENDMODULE
