MODULE add_use
! @format 3
! @section 13
! @expect ok
! @description Add adds a value, possibly negative, to a num or dnum variable (installed-facts.md section 1's examples Add reg1, -reg2; and Add mydnum, 500000000;).
! @output 7
! @output TRUE
! @exit 0
  VAR num reg1 := 10;
  VAR num reg2 := 3;
  VAR dnum mydnum := 9000000000;
  PROC main()
    Add reg1, -reg2;
    Add mydnum, 500000000;
    TPWrite "" \Num:=reg1;
    TPWrite "" \Bool:=mydnum = 9500000000;
  ENDPROC
ENDMODULE
