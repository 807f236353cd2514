MODULE connect_constant
! @format 2
! @section 4.15
! @expect semantic-error 8:13
! @description A constant is no connect target; refused at the target.
  CONST intnum ino := 1;
  PROC main()
    CONNECT ino WITH on_event;
  ENDPROC
  TRAP on_event
  ENDTRAP
ENDMODULE
