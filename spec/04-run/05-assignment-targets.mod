MODULE assignment_targets
! @format 3
! @section 4.5
! @expect ok
! @description The target forms of section 4.5's table: a component, a matrix element, a component of an array element; each changes only its part.
! @output home.x=15
! @output home.y=2
! @output matrix{2,3}=7
! @output matrix{3,2}=0
! @output posarr{2}.y=4
! @output posarr{1}.y=0
! @exit 0
  VAR pos home := [1, 2, 3];
  VAR num matrix{3, 3};
  VAR pos posarr{2};
  PROC main()
    VAR num x := 30;
    VAR num i := 2;
    VAR num j := 3;
    VAR num temp := 7;
    home.x := x / 2;
    matrix{i, j} := temp;
    posarr{i}.y := 4;
    TPWrite "home.x=" \Num:=home.x;
    TPWrite "home.y=" \Num:=home.y;
    TPWrite "matrix{2,3}=" \Num:=matrix{2, 3};
    TPWrite "matrix{3,2}=" \Num:=matrix{3, 2};
    TPWrite "posarr{2}.y=" \Num:=posarr{2}.y;
    TPWrite "posarr{1}.y=" \Num:=posarr{1}.y;
  ENDPROC
ENDMODULE
