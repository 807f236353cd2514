MODULE DebugBreak
! @format 2
! @section 9.2
! @expect semantic-error 7:5
! @description A module name hides any predefined object with the same name: within the task DebugBreak names the module, and calling it is refused at the name.
  PROC main()
    DebugBreak;
  ENDPROC
ENDMODULE
