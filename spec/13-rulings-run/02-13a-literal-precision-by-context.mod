MODULE rulings_literal_context
! @format 3
! @section 2.13
! @section 2.5
! @expect ok
! @description R-2.13-a: a literal is rounded to the precision of its context, num (single) or dnum (double), to nearest with ties to even: 16777217 is the single 16777216 but stays 16777217 as a dnum; 16777219 is the single 16777220; 9007199254740993 is the double 9007199254740992.
! @output num 16777217 = 16777216 TRUE
! @output dnum 16777217 = 16777216 FALSE
! @output dnum 16777217 written 16777217
! @output num 16777219 = 16777220 TRUE
! @output dnum 9007199254740993 = 9007199254740992 TRUE
! @exit 0
  PROC main()
    VAR num n := 16777217;
    VAR dnum d := 16777217;
    VAR num m := 16777219;
    VAR dnum big := 9007199254740993;
    TPWrite "num 16777217 = 16777216 " \Bool:=n = 16777216;
    TPWrite "dnum 16777217 = 16777216 " \Bool:=d = 16777216;
    TPWrite "dnum 16777217 written " \Dnum:=d;
    TPWrite "num 16777219 = 16777220 " \Bool:=m = 16777220;
    TPWrite "dnum 9007199254740993 = 9007199254740992 " \Bool:=big = 9007199254740992;
  ENDPROC
ENDMODULE
