MODULE if_manual_example
! @format 3
! @section 4.16
! @expect ok
! @description Section 4.16's example run with counter = 150, -5 and 50: the conditions are evaluated in turn until one is true, else the ELSE list runs.
! @output 100
! @output 0
! @output 51
! @exit 0
  PROC clamp(VAR num counter)
    IF counter > 100 THEN
      counter := 100;
    ELSEIF counter < 0 THEN
      counter := 0;
    ELSE
      counter := counter + 1;
    ENDIF
  ENDPROC
  PROC main()
    VAR num c;
    c := 150;
    clamp c;
    TPWrite "" \Num:=c;
    c := -5;
    clamp c;
    TPWrite "" \Num:=c;
    c := 50;
    clamp c;
    TPWrite "" \Num:=c;
  ENDPROC
ENDMODULE
