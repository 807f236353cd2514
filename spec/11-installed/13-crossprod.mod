MODULE crossprod_use
! @format 3
! @section 13
! @section 3.12
! @expect ok
! @description CrossProd gives the cross product of two vectors, the same as the operator pos * pos (section 3.12).
! @output [-3,6,-3]
! @output same as operator=TRUE
! @exit 0
  PROC main()
    VAR pos u := [1, 2, 3];
    VAR pos v := [4, 5, 6];
    VAR pos r;
    r := CrossProd(u, v);
    TPWrite "[" + NumToStr(r.x, 0) + "," + NumToStr(r.y, 0) + "," + NumToStr(r.z, 0) + "]";
    TPWrite "same as operator=" \Bool:=r = u * v;
  ENDPROC
ENDMODULE
