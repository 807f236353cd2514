MODULE late_binding_optional_arguments
! @format 3
! @section 4.6
! @section 5.2
! @expect ok
! @description Section 4.6's move with late binding: the optional arguments are bound by name when the call runs; both alternatives of \speed | \time, the same optional argument twice, a switch for a parameter that is not one, a value for a switch, an optional parameter named as a required argument (name := value) or a required one as an optional argument (\name := value) raise ERR_CALLPROC.
! @output speed 100
! @output time 20
! @output reltool
! @output both alternatives: 
! @output callproc
! @output twice: 
! @output callproc
! @output switch for a value: 
! @output callproc
! @output value for a switch: 
! @output callproc
! @output required form for an optional: 
! @output callproc
! @output optional form for a required: 
! @output callproc
! @exit 0
  PROC move(\switch reltool, num dest \num speed | num time)
    IF Present(reltool) TPWrite "reltool";
    IF Present(speed) TPWrite "speed " \Num:=speed;
    IF Present(time) TPWrite "time " \Num:=time;
  ENDPROC
  PROC main()
    % "move" % 1 \speed:=100;
    % "move" % 1 \time:=20;
    % "move" % \reltool, 1;
    TPWrite "both alternatives: ";
    % "move" % 1 \speed:=100 \time:=20;
    TPWrite "twice: ";
    % "move" % 1 \speed:=100 \speed:=50;
    TPWrite "switch for a value: ";
    % "move" % 1 \speed;
    TPWrite "value for a switch: ";
    % "move" % \reltool:=1, 1;
    TPWrite "required form for an optional: ";
    % "move" % 1, speed:=100;
    TPWrite "optional form for a required: ";
    % "move" % \dest:=1;
  ERROR
    IF ERRNO = ERR_CALLPROC THEN
      TPWrite "callproc";
      TRYNEXT;
    ENDIF
  ENDPROC
ENDMODULE
