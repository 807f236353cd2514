MODULE late_binding_literal_dnum
! @format 3
! @section 4.6
! @section 2.5
! @expect ok
! @description A numeric literal passed to a dnum parameter by a late-bound call is a dnum, as in a direct call (the literal takes its parameter's type): 4294967295 is not rounded to single precision.
! @output dnum=4294967295
! @output num=7
! @exit 0
  PROC show_dnum(dnum d)
    TPWrite "dnum=" \Dnum:=d;
  ENDPROC
  PROC show_num(num n)
    TPWrite "num=" \Num:=n;
  ENDPROC
  PROC main()
    % "show_dnum" % 4294967295;
    % "show_num" % 3 + 4;
  ENDPROC
ENDMODULE
