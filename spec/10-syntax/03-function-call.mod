MODULE function_call
! @section 3.11
! @expect ok
! @description The function calls printed in section 3.11, an empty argument list and <ID> as function name.
  VAR num x;
  VAR pos p1;
  VAR pos p2;
  PROC main()
    x := polar(3.937, 0.785398);
    x := polar(dist := 3.937, angle := 0.785398);
    x := cosine(45);
    x := cosine(0.785398\rad);
    x := dist(pnt:=p2);
    x := dist(\base:=p1, pnt:=p2);
    x := f();
    x := <ID>(1);
  ENDPROC
ENDMODULE
