MODULE rulings_cross_product
! @format 3
! @section 3.12
! @expect ok
! @description R-3.12-d: pos * pos is the cross product [y1 z2 - z1 y2, z1 x2 - x1 z2, x1 y2 - y1 x2]: x * y = z, y * x = -z, [1,2,3] * [4,5,6] = [-3,6,-3], a vector times itself is 0.
! @output x*y=[0,0,1]
! @output y*x=[0,0,-1]
! @output [1,2,3]*[4,5,6]=[-3,6,-3]
! @output [4,5,6]*[1,2,3]=[3,-6,3]
! @output v*v=[0,0,0]
! @exit 0
  PROC main()
    VAR pos x := [1, 0, 0];
    VAR pos y := [0, 1, 0];
    VAR pos a := [1, 2, 3];
    VAR pos b := [4, 5, 6];
    TPWrite "x*y=" \Pos:=x * y;
    TPWrite "y*x=" \Pos:=y * x;
    TPWrite "[1,2,3]*[4,5,6]=" \Pos:=a * b;
    TPWrite "[4,5,6]*[1,2,3]=" \Pos:=b * a;
    TPWrite "v*v=" \Pos:=a * a;
  ENDPROC
ENDMODULE
