MODULE connect_in_parameter
! @format 2
! @section 4.15
! @expect semantic-error 7:13
! @description A parameter used as connect target must be a VAR or INOUT parameter; an in parameter is refused at the target.
  PROC attach(intnum ino)
    CONNECT ino WITH on_event;
  ENDPROC
  TRAP on_event
  ENDTRAP
ENDMODULE
