MODULE decr_use
! @format 3
! @section 13
! @expect ok
! @description Decr subtracts 1 from a num or dnum variable.
! @output 4
! @output -1
! @output TRUE
! @exit 0
  VAR num reg1 := 5;
  VAR num zero;
  VAR dnum d := 10;
  PROC main()
    Decr reg1;
    Decr zero;
    Decr d;
    TPWrite "" \Num:=reg1;
    TPWrite "" \Num:=zero;
    TPWrite "" \Bool:=d = 9;
  ENDPROC
ENDMODULE
