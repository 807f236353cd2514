MODULE dim_use
! @format 3
! @section 11
! @expect ok
! @description Dim(datobj, dimno) gives the number of elements of the array in dimension dimno, 1 to 3 (chapter 11), for an array and for a {*} parameter bound to one.
! @output 2 3 4
! @output 10
! @exit 0
  VAR num cube{2, 3, 4};
  VAR num row{10};
  PROC size(num a{*})
    TPWrite "" \Num:=Dim(a, 1);
  ENDPROC
  PROC main()
    TPWrite NumToStr(Dim(cube, 1), 0) + " " + NumToStr(Dim(cube, 2), 0) + " " + NumToStr(Dim(cube, 3), 0);
    size row;
  ENDPROC
ENDMODULE
