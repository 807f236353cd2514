MODULE predefined_routine_without
! @format 2
! @section 5.3
! @section 11
! @section 4.6
! @expect semantic-error 9:16
! @description Without a user routine of that name, DebugBreak is the built-in procedure without parameters: the argument is refused as one too many.
  PROC main()
    DebugBreak 3;
  ENDPROC
ENDMODULE
