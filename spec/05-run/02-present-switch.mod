MODULE present_switch
! @format 3
! @section 5.2
! @expect ok
! @description Section 5.2's glue: switch parameters carry no value, only presence, tested with Present; of mutually exclusive ones at most one is given.
! @output off
! @output on
! @output neither
! @exit 0
  PROC glue(\switch on | switch off)
    IF Present(off) THEN
      TPWrite "off";
    ELSEIF Present(on) THEN
      TPWrite "on";
    ELSE
      TPWrite "neither";
    ENDIF
  ENDPROC
  PROC main()
    glue \off;
    glue \on;
    glue;
  ENDPROC
ENDMODULE
