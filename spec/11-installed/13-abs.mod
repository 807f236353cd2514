MODULE abs_use
! @format 3
! @section 13
! @expect ok
! @description Abs gives the absolute value.
! @output 3
! @output TRUE
! @output 0
! @exit 0
  PROC main()
    VAR num n := -3;
    TPWrite "" \Num:=Abs(n);
    TPWrite "" \Bool:=Abs(2.5) = 2.5;
    TPWrite "" \Num:=Abs(0);
  ENDPROC
ENDMODULE
