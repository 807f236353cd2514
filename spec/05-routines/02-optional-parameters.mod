MODULE optional_parameters
! @format 2
! @section 5.2
! @section 9.2
! @expect ok
! @description Section 5.2's glue and section 9.2's arcweld: mutually exclusive optional parameters, switch parameters tested with Present.
  VAR pos pos2;
  VAR pose p;
  PROC glue(\switch on | switch off, pos target)
    IF Present(off) THEN
      ! check presence of optional parameter 'off'
      DebugBreak;
    ENDIF
  ENDPROC
  PROC arcweld(pose position \num speed | num time)
  ENDPROC
  PROC main()
    glue\off, pos2;
    glue pos2;
    arcweld p \speed := 25;
    arcweld p \time := 2;
    arcweld p;
  ENDPROC
ENDMODULE
