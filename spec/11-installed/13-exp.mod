MODULE exp_use
! @format 3
! @section 13
! @expect ok
! @description Exp(x) gives e to the power x (installed-facts.md section 1).
! @output 1
! @output TRUE
! @exit 0
  PROC main()
    TPWrite "" \Num:=Exp(0);
    TPWrite "" \Bool:=Abs(Exp(1) - 2.71828) < 0.0001;
  ENDPROC
ENDMODULE
