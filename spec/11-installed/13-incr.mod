MODULE incr_use
! @format 3
! @section 13
! @expect ok
! @description Incr adds 1 to a num or dnum variable or persistent (installed-facts.md section 1, numeric instructions).
! @output 6
! @output 1
! @output TRUE
! @exit 0
  VAR num reg1 := 5;
  PERS num counter := 0;
  VAR dnum big := 4503599627370495;
  PROC main()
    Incr reg1;
    Incr counter;
    Incr big;
    TPWrite "" \Num:=reg1;
    TPWrite "" \Num:=counter;
    TPWrite "" \Bool:=big = 4503599627370496;
  ENDPROC
ENDMODULE
