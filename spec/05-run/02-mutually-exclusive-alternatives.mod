MODULE mutually_exclusive
! @format 3
! @section 5.2
! @section 4.6
! @expect ok
! @description Section 4.6's move: of the alternatives \speed | \time the one given is present and holds its value; the other is absent.
! @output speed 100
! @output time 20
! @output none
! @exit 0
  PROC move(\switch reltool, num dest \num speed | num time)
    IF Present(speed) THEN
      TPWrite "speed " \Num:=speed;
    ELSEIF Present(time) THEN
      TPWrite "time " \Num:=time;
    ELSE
      TPWrite "none";
    ENDIF
  ENDPROC
  PROC main()
    move \reltool, 1 \speed := 100;
    move \reltool, 1 \time := 20;
    move 1;
  ENDPROC
ENDMODULE
