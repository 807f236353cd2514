MODULE connect_pers_parameter
! @format 2
! @section 4.15
! @expect semantic-error 7:13
! @description A PERS parameter is no connect target; refused at the target.
  PROC attach(PERS num ino)
    CONNECT ino WITH on_event;
  ENDPROC
  TRAP on_event
  ENDTRAP
ENDMODULE
