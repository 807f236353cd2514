MODULE rulings_quaternion_product
! @format 3
! @section 3.12
! @section 2.14
! @expect ok
! @description R-3.12-d: orient * orient is the Hamilton product with q1 the scalar part: i j = k, j i = -k, k i = j, i i = -1, and [1,2,3,4] * [5,6,7,8] = [-60,12,30,24].
! @output i*j=[0,0,0,1]
! @output j*i=[0,0,0,-1]
! @output k*i=[0,0,1,0]
! @output i*i=[-1,0,0,0]
! @output 1*i=[0,1,0,0]
! @output [1,2,3,4]*[5,6,7,8]=[-60,12,30,24]
! @exit 0
  PROC main()
    VAR orient one := [1, 0, 0, 0];
    VAR orient i := [0, 1, 0, 0];
    VAR orient j := [0, 0, 1, 0];
    VAR orient k := [0, 0, 0, 1];
    VAR orient a := [1, 2, 3, 4];
    VAR orient b := [5, 6, 7, 8];
    TPWrite "i*j=" \Orient:=i * j;
    TPWrite "j*i=" \Orient:=j * i;
    TPWrite "k*i=" \Orient:=k * i;
    TPWrite "i*i=" \Orient:=i * i;
    TPWrite "1*i=" \Orient:=one * i;
    TPWrite "[1,2,3,4]*[5,6,7,8]=" \Orient:=a * b;
  ENDPROC
ENDMODULE
