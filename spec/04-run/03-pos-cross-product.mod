MODULE pos_cross_product
! @format 3
! @section 3.12
! @expect ok
! @description pos * pos is the cross product (section 3.12): x * y = z, y * x = -z, [1,2,3] * [4,5,6] = [-3,6,-3]; components printed one by one.
! @output z=[0,0,1]
! @output 0
! @output 0
! @output -1
! @output -3
! @output 6
! @output -3
! @exit 0
  PROC main()
    VAR pos x := [1, 0, 0];
    VAR pos y := [0, 1, 0];
    VAR pos u := [1, 2, 3];
    VAR pos v := [4, 5, 6];
    VAR pos r;
    r := x * y;
    IF r = [0, 0, 1] TPWrite "z=[0,0,1]";
    r := y * x;
    TPWrite "" \Num:=r.x;
    TPWrite "" \Num:=r.y;
    TPWrite "" \Num:=r.z;
    r := u * v;
    TPWrite "" \Num:=r.x;
    TPWrite "" \Num:=r.y;
    TPWrite "" \Num:=r.z;
  ENDPROC
ENDMODULE
