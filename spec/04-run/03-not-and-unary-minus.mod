MODULE not_and_unary_minus
! @format 3
! @section 3.12
! @expect ok
! @description NOT negates a bool; unary minus changes the sign of num and dnum (section 3.12).
! @output FALSE
! @output -5
! @output 5
! @output TRUE
! @exit 0
  PROC main()
    VAR bool t := TRUE;
    VAR num n := 5;
    VAR dnum d := 7;
    TPWrite "" \Bool:=NOT t;
    TPWrite "" \Num:=-n;
    TPWrite "" \Num:=-(-n);
    TPWrite "" \Bool:=-d = -7;
  ENDPROC
ENDMODULE
