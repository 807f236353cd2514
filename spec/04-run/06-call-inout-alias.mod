MODULE call_inout_alias
! @format 3
! @section 5.2
! @expect ok
! @description An inout parameter is an alias of its argument, a variable or a persistent (section 5.2): updates are visible through the argument at once.
! @output var during=3
! @output var after=3
! @output pers during=4
! @output pers after=4
! @exit 0
  VAR num v := 1;
  PERS num p := 1;
  PROC setv(INOUT num a)
    a := 3;
    TPWrite "var during=" \Num:=v;
  ENDPROC
  PROC setp(INOUT num a)
    a := 4;
    TPWrite "pers during=" \Num:=p;
  ENDPROC
  PROC main()
    setv v;
    TPWrite "var after=" \Num:=v;
    setp p;
    TPWrite "pers after=" \Num:=p;
  ENDPROC
ENDMODULE
