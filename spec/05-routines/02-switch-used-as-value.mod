MODULE switch_used_as_value
! @format 2
! @section 5.2
! @expect semantic-error 7:8
! @description A switch parameter has no value: the only uses are Present and passing it on; as a condition it is refused at its name.
  PROC glue(\switch on)
    IF on THEN
      DebugBreak;
    ENDIF
  ENDPROC
ENDMODULE
