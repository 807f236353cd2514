MODULE connect_routine_variable
! @format 2
! @section 4.15
! @expect semantic-error 8:13
! @description The target must be a module variable, not a routine variable; refused at the target.
  PROC main()
    VAR intnum local_ino;
    CONNECT local_ino WITH on_event;
  ENDPROC
  TRAP on_event
  ENDTRAP
ENDMODULE
