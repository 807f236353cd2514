MODULE cross_product
! @format 2
! @section 3.12
! @expect ok
! @description Row * pos * pos -> pos (cross product).
  VAR pos p1;
  VAR pos p2;
  VAR pos r;
  PROC main()
    r := p1 * p2;
  ENDPROC
ENDMODULE
