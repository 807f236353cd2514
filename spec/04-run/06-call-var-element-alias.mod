MODULE call_var_element_alias
! @format 3
! @section 5.2
! @section 3.6
! @expect ok
! @description An array element or a record component given to a var parameter is aliased: the update changes that element or component of the argument only.
! @output a=1,20,3
! @output p.y=8
! @output p.x=1
! @exit 0
  VAR num a{3} := [1, 2, 3];
  VAR pos p := [1, 2, 3];
  PROC set(VAR num x, num v)
    x := v;
  ENDPROC
  PROC main()
    set a{2}, 20;
    set p.y, 8;
    TPWrite "a=" + NumToStr(a{1}, 0) + "," + NumToStr(a{2}, 0) + "," + NumToStr(a{3}, 0);
    TPWrite "p.y=" \Num:=p.y;
    TPWrite "p.x=" \Num:=p.x;
  ENDPROC
ENDMODULE
