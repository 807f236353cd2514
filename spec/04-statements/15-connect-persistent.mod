MODULE connect_persistent
! @format 2
! @section 4.15
! @expect semantic-error 8:13
! @description The target must be a variable: a persistent is refused at the target.
  PERS num ino := 0;
  PROC main()
    CONNECT ino WITH on_event;
  ENDPROC
  TRAP on_event
  ENDTRAP
ENDMODULE
