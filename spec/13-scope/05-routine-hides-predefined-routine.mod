MODULE routine_hides_predefined_routine
! @format 2
! @section 5.3
! @expect ok
! @description A user routine hides a predefined routine of the same name: DebugBreak takes a num here.
  PROC DebugBreak(num level)
  ENDPROC
  PROC main()
    DebugBreak 3;
  ENDPROC
ENDMODULE
