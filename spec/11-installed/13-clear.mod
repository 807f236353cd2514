MODULE clear_use
! @format 3
! @section 13
! @expect ok
! @description Clear sets a num or dnum variable to 0.
! @output 0
! @output TRUE
! @exit 0
  VAR num reg1 := 42;
  VAR dnum d := 123;
  PROC main()
    Clear reg1;
    Clear d;
    TPWrite "" \Num:=reg1;
    TPWrite "" \Bool:=d = 0;
  ENDPROC
ENDMODULE
