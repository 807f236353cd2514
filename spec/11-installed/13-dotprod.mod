MODULE dotprod_use
! @format 3
! @section 13
! @expect ok
! @description DotProd gives the scalar product of two vectors.
! @output 32
! @output 0
! @exit 0
  PROC main()
    VAR pos u := [1, 2, 3];
    VAR pos v := [4, 5, 6];
    VAR pos x := [1, 0, 0];
    VAR pos y := [0, 1, 0];
    TPWrite "" \Num:=DotProd(u, v);
    TPWrite "" \Num:=DotProd(x, y);
  ENDPROC
ENDMODULE
