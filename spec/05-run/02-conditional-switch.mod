MODULE conditional_switch
! @format 3
! @section 3.11
! @section 5.2
! @expect ok
! @description A switch is passed on with the conditional syntax (section 3.11): \on ? high is present in the callee exactly when high is present in the caller; two conditional arguments may serve mutually exclusive parameters.
! @output on
! @output off
! @output neither
! @exit 0
  FUNC bool check(\switch on | switch off)
    IF Present(on) TPWrite "on";
    IF Present(off) TPWrite "off";
    IF NOT (Present(on) OR Present(off)) TPWrite "neither";
    RETURN TRUE;
  ENDFUNC
  PROC relay(\switch high | switch low)
    VAR bool ok;
    ok := check(\on ? high \off ? low);
  ENDPROC
  PROC main()
    relay \high;
    relay \low;
    relay;
  ENDPROC
ENDMODULE
