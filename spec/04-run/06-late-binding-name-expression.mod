MODULE late_binding_name_expression
! @format 3
! @section 4.6
! @expect ok
! @description Section 4.6's late binding, example 1: % "proc" + NumToStr(product_id, 0) % x, y, z; evaluates the name when it runs and calls proc2.
! @output proc2 6
! @exit 0
  VAR num product_id := 2;
  VAR num x := 1;
  VAR num y := 2;
  VAR num z := 3;
  PROC main()
    % "proc" + NumToStr(product_id, 0) % x, y, z;
  ENDPROC
  PROC proc1(num a, num b, num c)
    TPWrite "proc1" \Num:=a + b + c;
  ENDPROC
  PROC proc2(num a, num b, num c)
    TPWrite "proc2 " \Num:=a + b + c;
  ENDPROC
  PROC proc3(num a, num b, num c)
    TPWrite "proc3" \Num:=a + b + c;
  ENDPROC
ENDMODULE
